// Exports the entry point of a different ABI version than the host's.
#include "tessera/backend/PluginApi.h"

extern "C" __attribute__((visibility("default"))) void registerPlugin_v2(tessera::backend::PluginRegistry&) {}
