// Valid plugin whose load fails because its dependency is not on any search path.
#include "tessera/backend/PluginApi.h"

extern "C" int tesseraTestDependency();

TESSERA_REGISTER_PLUGIN(registry) {
    (void)registry;
    (void)tesseraTestDependency();
}
