#pragma once
// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// backends/common is shared: it includes no single backend.
#include "StreamoutBuffers.h"
