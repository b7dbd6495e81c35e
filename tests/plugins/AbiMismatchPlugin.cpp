// Exports the entry point of an older ABI version than the host's (a plugin
// built before the character commands joined the contract).
#include "tessera/backend/PluginApi.h"

extern "C" __attribute__((visibility("default"))) void registerPlugin_v1(tessera::backend::PluginRegistry&) {}
