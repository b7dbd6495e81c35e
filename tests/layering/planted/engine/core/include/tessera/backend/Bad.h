// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// The contract is part of tessera_core, below tessera_subdiv.
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/backend/SubdivMeshData.h"
