#pragma once
// A pass of the frame, declared in its own file beside its execute
// (DESIGN.md "The frame graph"; Falcor's RenderPass::reflect() and
// execute(), Filament's addPass(setup, execute)). Its header gives its
// name (kName, graph/PassId.h) and the outputs only it writes (kOutputs);
// each frame setup() says what the pass reads and writes (typed handles),
// whether it runs and why (an EffectDecision), the registry parameters it
// reads (PassSpec::parameters; a pass that had a scene::Pass bit is also
// invalidated by the parameters whose declaration names it) and its reuse
// key; execute() does the work. Indirect light for shading is declared too
// (FrameState::indirectLight, IndirectLight.h). A pass joins the frame with
// one line in PassTable.cpp (PassList.h); the renderer keeps the passes in
// that table.
#include "graph/FrameGraph.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/ParameterRegistry.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace lpv::renderer {

class GpuMemoryLedger;

// A graph pass's decision when no scene analysis stands behind it: it runs
// (or does not) for the reason given.
inline EffectDecision runsBecause(std::string why) {
    EffectDecision d;
    d.wanted = true;
    d.reason = std::move(why);
    return d;
}
inline EffectDecision skippedBecause(std::string why) {
    EffectDecision d;
    d.reason = std::move(why);
    return d;
}

// A resource a pass owns, described by asking GL when the graph needs it.
void importTexture(graph::FrameGraph& graph, graph::ResourceHandle name, std::function<GLuint()> id);

struct FrameState;

// Creates a pass's GL objects on its first run, so a pass that never runs
// holds no GPU memory; release() drops them again.
template <typename Gpu, typename Create> scene::Expected<void> createOnFirstRun(std::optional<Gpu>& gpu, Create create) {
    if (gpu)
        return {};
    auto created = create();
    if (!created)
        return std::unexpected(created.error());
    gpu.emplace(std::move(*created));
    return {};
}

// A pass around an object whose create() builds its shaders (so a shader
// error shows when the renderer is made): the pass, or that error.
template <typename Pass, typename Inner>
scene::Expected<std::unique_ptr<Pass>> createAround(scene::Expected<Inner> inner) {
    if (!inner)
        return std::unexpected(inner.error());
    return std::make_unique<Pass>(std::move(*inner));
}

// One entry of the frame's pass table.
class FramePass {
  public:
    virtual ~FramePass() = default;
    // Adds this frame's pass (or passes) and the resources only it owns to state.graph.
    virtual void addTo(FrameState& state) = 0;
    // After compile(): a pass the graph culled frees what it holds (a pass
    // that does not run holds no GPU memory).
    virtual void releaseIfCulled(const graph::FrameGraph&) {}
    // Names its own GL objects for ForwardRenderer::gpuMemory().
    virtual void addGpuMemory(GpuMemoryLedger&) const {}
};

// The form a pass takes in its own file: one graph pass named by `id`
// (graph/PassId.h): a word of its own, GraphPass("myPass"), or a
// registry pass's scene::Pass.
class GraphPass : public FramePass {
  public:
    explicit GraphPass(graph::PassId id) : id_(std::move(id)) {}
    explicit GraphPass(std::string_view name) : id_(name) {}
    const graph::PassId& id() const { return id_; }

    void addTo(FrameState& state) final {
        graph::PassSpec spec;
        spec.id = id_;
        setup(spec, state);
        spec.execute = [this, &state](graph::PassContext& ctx) { return execute(ctx, state); };
        addToGraph(state, std::move(spec));
    }
    void releaseIfCulled(const graph::FrameGraph& graph) final {
        if (!graph.produced(id_))
            release();
    }

  protected:
    // Declares this frame's reads, writes, decision and reuse key into `pass`
    // (and, through state.graph, any resource only this pass writes).
    virtual void setup(graph::PassSpec& pass, FrameState& state) = 0;
    virtual scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) = 0;
    // Frees its GPU objects: the graph culled it this frame.
    virtual void release() {}

  private:
    static void addToGraph(FrameState& state, graph::PassSpec spec);
    graph::PassId id_;
};

} // namespace lpv::renderer
