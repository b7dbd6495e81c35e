// Has the entry point but registers nothing.
#include "tessera/backend/PluginApi.h"

TESSERA_REGISTER_PLUGIN(registry) { (void)registry; }
