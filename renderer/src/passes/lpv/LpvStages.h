#pragma once
// The LPV's stages as passes of the frame (LpvPass.h has the kernels):
// injection, sky injection, the directed propagation's normals, the
// geometry volume, propagation and bounces, each defined in its own file
// (LpvInjectionStage.cpp...). They update the volumes in place in this
// order. A stage reads only LpvStageInputs, so LpvPass::run (tests and
// tools, no frame graph) runs the same stages under the same decisions:
// there is one schedule, the stages' own.
#include "frame/FramePass.h"
#include "passes/lpv/LpvPass.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lpv::renderer {

// What the stages are computed from: the frame's plan (ForwardRenderer) or
// LpvPass::run's arguments.
struct LpvStageInputs {
    LpvPass* lpv = nullptr;
    LpvSettings settings;
    // Whether the LPV runs this frame, and why not.
    bool runs = false;
    std::string offReason;
    // Where the VPLs come from: the sun's RSM, spot and point lights' RSMs, emissive surfaces.
    bool sun = false, local = false, emissive = false;
    EffectDecision sky; // sky injection
    std::vector<LpvCascade> cascades; // the LPV's, finest first
    // What every stage's output is computed within (the scene, its lights,
    // the volumes); nullopt for propagation and bounces while a visualizer
    // watches the computation (no reuse then).
    std::uint64_t key = 0;
    std::uint64_t skyKey = 0; // key and the sky's colour
    std::optional<std::uint64_t> propagationKey;
    std::function<LpvRsmInput()> rsm;
    std::function<std::vector<LpvLocalInput>()> localInputs;
    std::function<LpvSkyInput()> skyInput;
    // The geometry volume's sources: the camera's G-buffer (null: none) and
    // the scene's own GV (null: the GV comes from the views).
    const LpvCameraInput* camera = nullptr;
    bool cameraGv = false; // the GV reads last frame's camera G-buffer (a graph history read)
    std::function<const LpvSceneGeometry*()> sceneGeometry;

    // Injection's and propagation's decision: the LPV runs, fed by what.
    EffectDecision decision() const;
    // "the LPV does not run: why", the decision of a stage of an LPV that does not run.
    EffectDecision off() const;
};

// A stage, defined in its own file: its declaration (Falcor's reflect(): the
// decision, reads, writes and key) and its work, both from LpvStageInputs
// alone; `resources` (may be null) declares what else the frame learns of
// with it: graph resources, the indirect light shading reads (IndirectLight.h).
struct LpvStageDefinition {
    scene::Pass id = scene::Pass::None;
    void (*declare)(graph::PassSpec& pass, const LpvStageInputs& in) = nullptr;
    void (*run)(const LpvStageInputs& in) = nullptr;
    void (*resources)(FrameState& state) = nullptr;
};

extern const LpvStageDefinition lpvInjectionStage;   // LpvInjectionStage.cpp
extern const LpvStageDefinition skyInjectionStage;   // SkyInjectionStage.cpp
extern const LpvStageDefinition lpvNormalsStage;     // LpvNormalsStage.cpp
extern const LpvStageDefinition geometryVolumeStage; // GeometryVolumeStage.cpp
extern const LpvStageDefinition lpvPropagationStage; // LpvPropagationStage.cpp
extern const LpvStageDefinition lpvBouncesStage;     // LpvBouncesStage.cpp

// A stage as a pass of the frame.
class LpvStage final : public GraphPass {
  public:
    explicit LpvStage(const LpvStageDefinition& stage) : GraphPass(stage.id), stage_(stage) {}
    const LpvStageDefinition& definition() const { return stage_; }

  protected:
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    const LpvStageDefinition& stage_;
};

// The stages in their order: the frame's pass table and LpvPass::run both take them from here.
std::vector<std::unique_ptr<LpvStage>> makeLpvStages();

} // namespace lpv::renderer
