// A library the test plugin links against but the loader cannot find.
extern "C" __attribute__((visibility("default"))) int tesseraTestDependency() { return 7; }
