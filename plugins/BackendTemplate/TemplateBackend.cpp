// The template's entry point: registers TemplateBackend (TemplateBackend.h)
// under the name "template".
#include "TemplateBackend.h"

namespace {

using namespace tessera;

backend::Backend* create() { return new plugins::TemplateBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace

TESSERA_REGISTER_PLUGIN(registry) { registry.registerBackend({"template", &create, &destroy}); }
