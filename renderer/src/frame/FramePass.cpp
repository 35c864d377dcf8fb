#include "frame/FramePass.h"

#include "frame/FrameState.h"

namespace lpv::renderer {

void importTexture(graph::FrameGraph& graph, graph::ResourceHandle name, std::function<GLuint()> id) {
    graph.importResource(name, [id = std::move(id)] {
        const GLuint t = id();
        return graph::ImportedView{t, graph::queryTexture(t)};
    });
}

void GraphPass::addToGraph(FrameState& state, graph::PassSpec spec) { state.graph.addPass(std::move(spec)); }

} // namespace lpv::renderer
