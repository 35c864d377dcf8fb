#pragma once
// Emissive surfaces' VPLs on the GPU (lpvref::sampleEmissiveVpls, docs/lpv.md
// "Local lights, emissive surfaces and bounces"): position (w = 1), normal and
// flux in three RGBA32F 2D arrays of one layer, size^2 >= the VPL count, in
// the form LpvPass injects local VPLs from. Uploaded once per scene change.
#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <vector>

namespace lpv::renderer {

class EmissiveVplBuffer {
  public:
    void upload(const std::vector<lpvref::Vpl>& vpls);
    bool empty() const { return count_ == 0; }
    int count() const { return count_; }
    LpvLocalInput input() const;
    std::size_t allocatedBytes() const { return std::size_t(size_) * std::size_t(size_) * 48; }

  private:
    Texture position_, normal_, flux_;
    int size_ = 0, count_ = 0;
};

} // namespace lpv::renderer
