#include "tessera/cli/FeatureMaskText.h"

#include "tessera/cli/NumberList.h"

#include <string>

namespace tessera::cli {

Result<device::FeatureMask> parseFeatureMask(std::string_view list) {
    device::FeatureMask mask;
    for (std::string_view word : splitList(list)) {
        const std::optional<device::FeatureMask> feature = device::featureNamed(word);
        if (!feature)
            return fail("unknown feature \"", std::string(word), "\" (known: ", device::featureMaskNames(), ")");
        mask.bits |= feature->bits;
    }
    return mask;
}

} // namespace tessera::cli
