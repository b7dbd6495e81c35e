// A valid shared module that is not a Tessera plugin: no entry point at all.
extern "C" __attribute__((visibility("default"))) int notATesseraPlugin() { return 42; }
