#include "lpv/renderer/DependencyVersions.h"

namespace lpv::renderer {

std::vector<scene::DependencyVersion> dependencyVersions() {
    // libepoxy has no version macro or call; pkg-config's version at configure time it is.
    return {{"libepoxy", LPV_EPOXY_VERSION, "built against"}};
}

} // namespace lpv::renderer
