#include "tessera/core/OutOfDeviceMemory.h"

namespace tessera {

// The key function: the vtable and type info live in tessera_core only, so
// the GPU layer that throws and the host that catches agree on one type.
OutOfDeviceMemory::~OutOfDeviceMemory() = default;

} // namespace tessera
