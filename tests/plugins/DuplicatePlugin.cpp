// Registers a backend under the name "null", which the real null backend owns.
#include "tessera/backend/PluginApi.h"

namespace {
tessera::backend::Backend* create() { return nullptr; }
void destroy(tessera::backend::Backend*) {}
} // namespace

TESSERA_REGISTER_PLUGIN(registry) { registry.registerBackend({"null", &create, &destroy}); }
