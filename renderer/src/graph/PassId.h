#pragma once
// A pass's one name in the frame: its graph node, its GPU timer row,
// `lpv render --graph` and `--dump`. A pass declares it in its own file
// (GraphPass's constructor) as a word, "radiosityIndirect"; nothing else
// needs to learn it. Passes that existed before names were free-standing
// also carry their scene::Pass bit (ParameterRegistry.h): parameters whose
// declaration names that bit invalidate them. A pass without a bit lists
// the registry keys it reads itself (PassSpec::parameters), which is the
// form for a new pass.
#include "lpv/scene/ParameterRegistry.h"

#include <string>
#include <string_view>

namespace lpv::renderer::graph {

class PassId {
  public:
    PassId() = default;
    // A registry pass: its name is scene::passName(pass). Implicit, so the
    // graph's queries take the enum as they did.
    PassId(scene::Pass pass) : name_(scene::passName(pass)), bit_(pass) {}
    // A pass named in its own file.
    explicit PassId(std::string_view name) : name_(name) {}

    const std::string& name() const { return name_; }
    // scene::Pass::None for a pass named in its own file.
    scene::Pass bit() const { return bit_; }
    bool empty() const { return name_.empty(); }

    friend bool operator==(const PassId& a, const PassId& b) { return a.name_ == b.name_; }

  private:
    std::string name_;
    scene::Pass bit_ = scene::Pass::None;
};

} // namespace lpv::renderer::graph
