#pragma once
// The frame graph (DESIGN.md "The frame graph"; Filament's FrameGraph and
// Falcor's RenderGraph are the models). Each frame the renderer declares its
// resources and passes; compile() orders the passes by what they read and
// write, culls those whose decision says they do not run (and those whose
// outputs nothing reads), decides which outputs can be reused, and
// allocates graph-owned targets; execute() runs the rest, each inside a GPU
// timer scope named by the pass.
//
// Reuse: a pass's key hashes what its output is computed from: its own
// inputs (scene generation, lights, camera; given by the renderer), the
// parameters the registry says invalidate it and those it declares it
// reads (PassSpec::parameters), and the versions of the
// resources it reads (a written resource's version is its writer's key).
// A pass is reused when its key equals the key of its last run. Passes that
// update a resource in place form a chain: when one of them reruns, all do.
#include "frame/FrameContext.h"
#include "graph/PassId.h"
#include "graph/ResourceDesc.h"
#include "graph/ResourceHandle.h"
#include "lpv/renderer/FrameGraphReport.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::renderer::graph {

// How a resource's memory is owned.
enum class Lifetime {
    Imported,  // a pass owns the GL object; the graph only knows its name and shape
    Transient, // the graph allocates it for this frame from a pool; it is gone after the frame
    History,   // the graph allocates it and keeps it across frames (read before written: last frame's)
};

// An imported resource as its owner shows it, asked when a pass executes
// (owners allocate on their first run, so the name is only known then).
struct ImportedView {
    GLuint id = 0;
    ResourceDesc desc;
};

class PassContext;

struct PassSpec {
    PassId id; // its one name (PassId.h)
    // Culled when !runs(); the reason goes to the report.
    EffectDecision decision;
    // A read sees the resource as the passes added before this one left it
    // (Filament's versions): the graph runs it after that version's writer
    // and before the next writer.
    std::vector<ResourceHandle> reads;
    // A name in both reads and writes is updated in place.
    std::vector<ResourceHandle> writes;
    // History resources read as the last frame left them (no pass added
    // before this one writes them this frame): the LPV's geometry volume
    // reads the last frame's camera G-buffer.
    std::vector<ResourceHandle> readsHistory;
    // Registry keys (scene/ParameterDeclarations.cpp) this pass reads besides
    // those whose declaration names the pass: their values join its reuse
    // key, and a change reruns it with "KEY changed". A key the registry does
    // not declare is an error of compile().
    std::vector<std::string> parameters;
    // What the output is computed from besides parameters and inputs (scene
    // generation, lights, camera...). nullopt: never reused, runs every frame.
    std::optional<std::uint64_t> inputsKey;
    // Runs even when nothing reads its outputs (it draws the image).
    bool final = false;
    std::function<scene::Expected<void>(PassContext&)> execute;
};

class PassContext {
  public:
    // The GL name of a resource this pass declared (read or write).
    // Undeclared: throws std::logic_error, which execute() turns into an error value.
    GLuint id(ResourceHandle resource) const;
    // The next texture unit no other binding of this pass uses.
    GLuint allocateUnit();
    // Binds a declared texture to a fresh unit and points the sampler uniform at it.
    GLuint bindTexture(GLuint program, GLint samplerLocation, ResourceHandle resource);
    const FrameContext& frame;

  private:
    friend class FrameGraph;
    PassContext(const FrameContext& f, const class FrameGraph& g, const PassSpec& p) : frame(f), graph_(g), pass_(p) {}
    const FrameGraph& graph_;
    const PassSpec& pass_;
    GLuint nextUnit_ = 0;
};

class FrameGraph {
  public:
    // Texture units the passes' own binds never get (MaterialGpu binds
    // units 8..15 per draw): allocateUnit() skips [first, last].
    void reserveUnits(GLuint first, GLuint last) { reservedUnits_ = {first, last}; }

    // Starts a frame's declarations; owned targets, pools and last keys are kept.
    void beginFrame();

    void importResource(ResourceHandle name, std::function<ImportedView()> view, std::uint64_t initialVersion = 0);
    // A graph-owned target. A History target keeps its content across frames
    // while its description stays the same; `initialVersion` names that content.
    void createResource(ResourceHandle name, ResourceDesc desc, Lifetime lifetime, std::uint64_t initialVersion = 0);
    void addPass(PassSpec spec);

    // Orders, culls, decides reuse (only when `reuse`), allocates. Errors: a
    // pass that reads or writes an undeclared resource, a cycle.
    scene::Expected<void> compile(const scene::ParameterSet& params, bool reuse);
    // Runs every pass compile() kept, each timed under its name.
    scene::Expected<void> execute(const FrameContext& frame);

    // The last frame's passes, reads, writes (with shapes) and reasons; built on first call after execute().
    const FrameGraphReport& report() const;
    // A pass's status in the last compile (nullopt: not declared).
    std::optional<PassStatus> status(const PassId& pass) const;
    // After execute(): a resource's GL name and shape (0 / empty if the frame did not declare it).
    // By name: what a user asked for (--dump NAME) or a report listed.
    GLuint resourceId(std::string_view name) const;
    GLuint resourceId(ResourceHandle resource) const { return resourceId(resource.name()); }
    std::optional<ResourceDesc> resourceDesc(std::string_view name) const;
    std::vector<std::string> resourceNames() const;
    // Whether the last frame's pass ran or was reused (its outputs are valid).
    bool produced(const PassId& pass) const;
    // Forgets a pass's last key: its next frame runs it (its owner freed its outputs).
    void forget(const PassId& pass) { last_.erase(pass.name()); }

  private:
    friend class PassContext;
    struct Resource {
        std::string name;
        Lifetime lifetime = Lifetime::Imported;
        std::function<ImportedView()> view; // Imported
        ResourceDesc desc;                  // Transient, History
        std::uint64_t version = 0;          // content before this frame's first writer
    };
    // One read of a pass: which pass wrote the version it sees (-1: the
    // content the frame started with).
    struct Access {
        std::string resource;
        int producer = -1;
    };
    struct LastRun {
        std::uint64_t key = 0;
        std::uint64_t inputsKey = 0;
        std::vector<std::string> parameterKeys; // the registry's for the pass, then its declared ones
        std::vector<scene::ParameterValue> parameters;
        std::map<std::string, std::uint64_t> inputVersions;
    };
    const Resource* findResource(std::string_view name) const;
    ImportedView viewOf(const Resource& r) const;
    scene::Expected<void> resolveVersions();
    scene::Expected<std::vector<std::size_t>> order() const;
    void decideReuse(const scene::ParameterSet& params, bool reuse);
    void allocateOwned();

    std::vector<Resource> resources_;
    std::vector<PassSpec> passes_;
    std::vector<std::size_t> order_;            // indices of passes_ in execution order
    std::vector<std::vector<Access>> inputs_;   // per passes_ index
    std::vector<std::set<std::size_t>> edges_;  // per passes_ index: passes that must run after it
    std::map<std::string, int, std::less<>> finalWriter_; // per resource: its last writer this frame
    std::vector<PassStatus> status_;            // per passes_ index
    std::vector<std::string> reasons_;          // per passes_ index
    std::vector<LastRun> pending_;              // per passes_ index: what a run now records
    std::map<std::string, LastRun, std::less<>> last_; // per pass name: its last run
    std::map<std::string, Texture, std::less<>> owned_;         // History and this frame's Transient targets
    std::map<std::string, ResourceDesc, std::less<>> ownedDesc_;
    std::vector<std::pair<ResourceDesc, Texture>> pool_;        // transient targets free for reuse
    std::set<std::string, std::less<>> fresh_;
    std::pair<GLuint, GLuint> reservedUnits_{1, 0}; // none                  // owned targets allocated this frame
    mutable FrameGraphReport report_;
    mutable bool reportStale_ = false;
};

} // namespace lpv::renderer::graph
