#include "graph/FrameGraph.h"

#include "graph/ContentHash.h"

#include <algorithm>
#include <queue>
#include <ranges>
#include <set>
#include <stdexcept>

namespace lpv::renderer::graph {

using scene::ErrorCode;
using scene::makeError;

namespace {

bool contains(const std::vector<ResourceHandle>& handles, std::string_view name) {
    return std::ranges::any_of(handles, [name](ResourceHandle h) { return h.name() == name; });
}

// The registry keys whose declaration names this pass's scene::Pass bit
// (none for a pass named in its own file: it lists what it reads). Built
// whole on first use, which C++ makes thread-safe, and only read after:
// renderers on several threads (the editor's frame worker, a video export,
// the A/B view) share it.
const std::vector<std::string>& invalidatingKeys(const PassId& pass) {
    static const std::map<std::uint32_t, std::vector<std::string>> byBit = [] {
        std::map<std::uint32_t, std::vector<std::string>> keys;
        for (const scene::Pass bit : scene::allPasses())
            for (const scene::ParameterInfo& info : scene::ParameterRegistry::instance().all())
                if (scene::any(info.invalidates, bit))
                    keys[std::uint32_t(bit)].push_back(info.key);
        return keys;
    }();
    static const std::vector<std::string> none;
    const auto it = byBit.find(std::uint32_t(pass.bit()));
    return it == byBit.end() ? none : it->second;
}

// The parameters a pass's output depends on: the keys whose registry entry
// names the pass, then those it declares reading (PassSpec::parameters).
std::vector<std::string> parameterKeys(const PassSpec& p) {
    std::vector<std::string> keys = invalidatingKeys(p.id);
    for (const std::string& key : p.parameters)
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            keys.push_back(key);
    return keys;
}

// The handles' names, for the bookkeeping below that keys by name.
auto names(const std::vector<ResourceHandle>& handles) { return handles | std::views::transform(&ResourceHandle::str); }

} // namespace

// --- PassContext ---

GLuint PassContext::id(ResourceHandle resource) const {
    const std::string_view name = resource.name();
    if (!contains(pass_.reads, name) && !contains(pass_.writes, name) && !contains(pass_.readsHistory, name))
        throw std::logic_error("pass " + pass_.id.name() + " uses '" + resource.str() +
                               "', which it did not declare");
    const auto* r = graph_.findResource(name);
    return r ? graph_.viewOf(*r).id : 0;
}

GLuint PassContext::allocateUnit() {
    const auto [first, last] = graph_.reservedUnits_;
    if (nextUnit_ >= first && nextUnit_ <= last)
        nextUnit_ = last + 1;
    return nextUnit_++;
}

GLuint PassContext::bindTexture(GLuint program, GLint samplerLocation, ResourceHandle resource) {
    const GLuint unit = allocateUnit();
    glBindTextureUnit(unit, id(resource));
    glProgramUniform1i(program, samplerLocation, GLint(unit));
    return unit;
}

// --- FrameGraph: declarations ---

void FrameGraph::beginFrame() {
    report_ = {};
    reportStale_ = false;
    resources_.clear();
    passes_.clear();
    order_.clear();
    status_.clear();
    reasons_.clear();
    pending_.clear();
}

void FrameGraph::importResource(ResourceHandle name, std::function<ImportedView()> view, std::uint64_t initialVersion) {
    resources_.push_back({name.str(), Lifetime::Imported, std::move(view), {}, initialVersion});
}

void FrameGraph::createResource(ResourceHandle name, ResourceDesc desc, Lifetime lifetime, std::uint64_t initialVersion) {
    resources_.push_back({name.str(), lifetime, {}, desc, initialVersion});
}

void FrameGraph::addPass(PassSpec spec) { passes_.push_back(std::move(spec)); }

const FrameGraph::Resource* FrameGraph::findResource(std::string_view name) const {
    for (const Resource& r : resources_)
        if (r.name == name)
            return &r;
    return nullptr;
}

ImportedView FrameGraph::viewOf(const Resource& r) const {
    if (r.lifetime == Lifetime::Imported)
        return r.view ? r.view() : ImportedView{};
    const auto it = owned_.find(r.name);
    return {it == owned_.end() ? 0u : it->second.id(), r.desc};
}

// --- compile ---

scene::Expected<void> FrameGraph::resolveVersions() {
    // Walk the passes as added: a read sees the last write before it; a write
    // runs after the previous writer and after every reader of the version it replaces.
    const std::size_t n = passes_.size();
    inputs_.assign(n, {});
    edges_.assign(n, {});
    finalWriter_.clear();
    std::map<std::string, std::vector<std::size_t>, std::less<>> readersOf;
    for (std::size_t i = 0; i < n; ++i) {
        if (status_[i] == PassStatus::Culled)
            continue;
        const PassSpec& p = passes_[i];
        for (const std::string& key : p.parameters)
            if (!scene::ParameterRegistry::instance().find(key))
                return makeError(ErrorCode::InvalidValue, "frame graph", p.id.name(),
                                 "reads parameter '" + key + "', which the registry does not declare");
        for (const auto* list : {&p.readsHistory, &p.reads})
            for (const std::string& name : names(*list)) {
                const auto w = finalWriter_.find(name);
                const int producer = w == finalWriter_.end() ? -1 : w->second;
                if (list == &p.readsHistory && producer >= 0)
                    return makeError(ErrorCode::InvalidValue, "frame graph", p.id.name(),
                                     "reads last frame's '" + name + "', but " +
                                         passes_[std::size_t(producer)].id.name() + " writes it earlier");
                inputs_[i].push_back({name, producer});
                if (producer >= 0)
                    edges_[std::size_t(producer)].insert(i);
                readersOf[name].push_back(i);
            }
        for (const std::string& name : names(p.writes)) {
            for (std::size_t r : readersOf[name])
                if (r != i)
                    edges_[r].insert(i);
            readersOf[name].clear();
            if (const auto w = finalWriter_.find(name); w != finalWriter_.end() && std::size_t(w->second) != i)
                edges_[std::size_t(w->second)].insert(i);
            finalWriter_[name] = int(i);
        }
    }
    return {};
}

scene::Expected<std::vector<std::size_t>> FrameGraph::order() const {
    // Kahn's algorithm over the version edges; among ready passes the one added first runs first.
    const std::size_t n = passes_.size();
    std::vector<int> incoming(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (status_[i] != PassStatus::Culled)
            for (std::size_t j : edges_[i])
                if (status_[j] != PassStatus::Culled)
                    ++incoming[j];
    std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>> ready;
    std::size_t live = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (status_[i] != PassStatus::Culled) {
            ++live;
            if (incoming[i] == 0)
                ready.push(i);
        }
    std::vector<std::size_t> out;
    while (!ready.empty()) {
        const std::size_t i = ready.top();
        ready.pop();
        out.push_back(i);
        for (std::size_t j : edges_[i])
            if (status_[j] != PassStatus::Culled && --incoming[j] == 0)
                ready.push(j);
    }
    if (out.size() != live) {
        std::string stuck;
        for (std::size_t i = 0; i < n; ++i)
            if (status_[i] != PassStatus::Culled && incoming[i] > 0)
                stuck += (stuck.empty() ? "" : ", ") + passes_[i].id.name();
        return makeError(ErrorCode::InvalidValue, "frame graph", "order",
                         "the passes " + stuck + " depend on each other in a cycle");
    }
    return out;
}

scene::Expected<void> FrameGraph::compile(const scene::ParameterSet& params, bool reuse) {
    const std::size_t n = passes_.size();
    status_.assign(n, PassStatus::Ran);
    reasons_.assign(n, "");
    pending_.assign(n, LastRun{});
    std::set<std::string, std::less<>> ids;
    for (std::size_t i = 0; i < n; ++i) {
        const PassSpec& p = passes_[i];
        if (p.id.empty() || !ids.insert(p.id.name()).second)
            return makeError(ErrorCode::InvalidValue, "frame graph", p.id.name(), "each pass needs its own name");
        for (const auto* list : {&p.reads, &p.writes, &p.readsHistory})
            for (const std::string& name : names(*list))
                if (!findResource(name))
                    return makeError(ErrorCode::InvalidValue, "frame graph", p.id.name(),
                                     "uses '" + name + "', which no resource of the frame is called");
        for (const std::string& name : names(p.readsHistory))
            if (findResource(name)->lifetime != Lifetime::History)
                return makeError(ErrorCode::InvalidValue, "frame graph", p.id.name(),
                                 "reads '" + name + "' as last frame's, but it is not a history resource");
        if (!p.decision.runs()) {
            status_[i] = PassStatus::Culled;
            reasons_[i] = p.decision.reason;
        }
    }
    if (auto ok = resolveVersions(); !ok)
        return ok;
    // Passes nothing needs: keep the final passes and, transitively, the writers of the versions kept passes read.
    {
        std::vector<bool> needed(n, false);
        std::vector<std::size_t> stack;
        for (std::size_t i = 0; i < n; ++i)
            if (status_[i] != PassStatus::Culled && passes_[i].final) {
                needed[i] = true;
                stack.push_back(i);
            }
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            for (const Access& a : inputs_[i])
                if (a.producer >= 0 && !needed[std::size_t(a.producer)]) {
                    needed[std::size_t(a.producer)] = true;
                    stack.push_back(std::size_t(a.producer));
                }
        }
        for (std::size_t i = 0; i < n; ++i)
            if (status_[i] != PassStatus::Culled && !needed[i]) {
                status_[i] = PassStatus::Culled;
                reasons_[i] = "nothing this frame reads its outputs";
            }
    }
    auto ordered = order();
    if (!ordered)
        return std::unexpected(ordered.error());
    order_ = std::move(*ordered);
    for (std::size_t i = 0; i < n; ++i)
        if (status_[i] == PassStatus::Culled)
            last_.erase(passes_[i].id.name()); // its owner may free what it wrote
    allocateOwned();
    decideReuse(params, reuse);
    return {};
}

void FrameGraph::allocateOwned() {
    // This frame's transient targets come from the pool of last frame's.
    for (auto it = owned_.begin(); it != owned_.end();) {
        const Resource* r = findResource(it->first);
        if (!r || r->lifetime == Lifetime::Transient || r->desc != ownedDesc_[it->first]) {
            if (!r || r->lifetime == Lifetime::Transient)
                pool_.emplace_back(ownedDesc_[it->first], std::move(it->second));
            ownedDesc_.erase(it->first);
            it = owned_.erase(it);
        } else {
            ++it;
        }
    }
    fresh_.clear();
    std::vector<std::pair<ResourceDesc, Texture>> unused = std::move(pool_);
    pool_.clear();
    for (Resource& r : resources_) {
        if (r.lifetime == Lifetime::Imported || owned_.count(r.name))
            continue;
        bool written = false;
        for (std::size_t i = 0; i < passes_.size(); ++i)
            written |= status_[i] != PassStatus::Culled && contains(passes_[i].writes, r.name);
        if (!written)
            continue;
        auto match = std::find_if(unused.begin(), unused.end(), [&](const auto& e) { return e.first == r.desc; });
        if (match != unused.end()) {
            owned_[r.name] = std::move(match->second);
            unused.erase(match);
        } else {
            owned_[r.name] = allocateTexture(r.desc);
        }
        ownedDesc_[r.name] = r.desc;
        fresh_.insert(r.name); // new storage: its writers run, and history readers find nothing in it
        if (r.lifetime == Lifetime::History)
            r.version = 0;
    }
    // Pooled targets no resource of this frame took are freed with `unused`.
}

void FrameGraph::decideReuse(const scene::ParameterSet& params, bool reuse) {
    // A written version is named by its writer's key; a version the frame
    // started with, by what the resource's owner says it holds.
    std::vector<std::map<std::string, std::uint64_t, std::less<>>> written(passes_.size());
    auto versionOf = [&](const Access& a) {
        return a.producer >= 0 ? written[std::size_t(a.producer)][a.resource] : findResource(a.resource)->version;
    };
    std::vector<bool> rerun(passes_.size(), false);
    for (std::size_t i : order_) {
        const PassSpec& p = passes_[i];
        LastRun& run = pending_[i];
        run.parameterKeys = parameterKeys(p);
        for (const std::string& key : run.parameterKeys)
            run.parameters.push_back(params.get(key));
        for (const Access& a : inputs_[i])
            run.inputVersions[a.resource] = versionOf(a);
        run.inputsKey = p.inputsKey.value_or(0);
        ContentHash h;
        h.add(std::string_view(p.id.name())).add(run.inputsKey).add(run.parameters);
        for (const auto& [name, v] : run.inputVersions)
            h.add(std::string_view(name)).add(v);
        run.key = h.value();
        for (const std::string& name : names(p.writes))
            written[i][name] = ContentHash().add(run.key).add(std::string_view(name)).value();

        const auto last = last_.find(p.id.name());
        std::string& why = reasons_[i];
        if (!p.inputsKey) {
            why = "runs every frame";
        } else if (!reuse) {
            why = "reuse is off (lpv.reuse = false)";
        } else if (last == last_.end()) {
            why = "nothing to reuse: first run";
        } else if (last->second.key != run.key) {
            const LastRun& was = last->second;
            if (was.inputsKey != run.inputsKey)
                why = "the scene, lights or camera changed";
            for (std::size_t k = 0; why.empty() && k < run.parameters.size(); ++k) {
                const auto at = std::find(was.parameterKeys.begin(), was.parameterKeys.end(), run.parameterKeys[k]);
                if (at == was.parameterKeys.end() ||
                    was.parameters[std::size_t(at - was.parameterKeys.begin())] != run.parameters[k])
                    why = run.parameterKeys[k] + " changed";
            }
            for (const auto& [name, v] : run.inputVersions)
                if (why.empty() && (!was.inputVersions.count(name) || was.inputVersions.at(name) != v))
                    why = "its input " + name + " changed";
            if (why.empty())
                why = "its inputs changed";
        } else {
            for (const std::string& name : names(p.writes)) {
                if (why.empty() && findResource(name)->lifetime == Lifetime::Transient)
                    why = name + " is transient: nothing is kept";
                if (why.empty() && fresh_.count(name))
                    why = name + " was (re)allocated";
            }
        }
        rerun[i] = !why.empty();
    }
    // The memory of a resource holds only its last version. Its writers, and
    // the passes that read an earlier version, form a chain: when one of them
    // reruns, every writer reruns, so the earlier versions exist again.
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [resource, last] : finalWriter_) {
            std::vector<std::size_t> members, writers;
            for (std::size_t i : order_) {
                if (contains(passes_[i].writes, resource)) {
                    members.push_back(i);
                    writers.push_back(i);
                    continue;
                }
                for (const Access& a : inputs_[i])
                    if (a.resource == resource && a.producer != last)
                        members.push_back(i);
            }
            const auto dirty = std::find_if(members.begin(), members.end(), [&](std::size_t i) { return rerun[i]; });
            if (dirty == members.end())
                continue;
            for (std::size_t w : writers)
                if (!rerun[w]) {
                    rerun[w] = true;
                    changed = true;
                    reasons_[w] = "reruns with " + passes_[*dirty].id.name() + " (they share " + resource + ")";
                }
        }
    }
    for (std::size_t i : order_) {
        status_[i] = rerun[i] ? PassStatus::Ran : PassStatus::Reused;
        if (!rerun[i])
            reasons_[i] = "nothing it is computed from changed";
    }
}

// --- execute ---

scene::Expected<void> FrameGraph::execute(const FrameContext& frame) {
    for (std::size_t i : order_) {
        if (status_[i] != PassStatus::Ran)
            continue;
        const PassSpec& p = passes_[i];
        const std::string name = p.id.name();
        PassContext context(frame, *this, p);
        scene::Expected<void> ok;
        frame.timer.begin(name);
        try {
            ok = p.execute(context);
        } catch (const std::logic_error& e) {
            ok = makeError(ErrorCode::InvalidValue, "frame graph", name, e.what());
        }
        frame.timer.end(name);
        if (!ok) {
            last_.erase(p.id.name());
            return ok;
        }
        last_[p.id.name()] = pending_[i];
    }
    reportStale_ = true; // built when asked for: describing imported targets asks GL
    return {};
}

const FrameGraphReport& FrameGraph::report() const {
    if (!reportStale_)
        return report_;
    reportStale_ = false;
    report_ = {};
    // The shapes are the ones owners allocated while running.
    auto entry = [&](std::size_t i) {
        const PassSpec& p = passes_[i];
        GraphPassReport r{p.id.name(), status_[i], reasons_[i], {}, {}};
        for (const std::string& name : names(p.readsHistory))
            r.reads.push_back(name + " (last frame's)");
        for (const std::string& name : names(p.reads))
            if (!contains(p.writes, name))
                r.reads.push_back(name);
        for (const std::string& name : names(p.writes))
            r.writes.push_back({name + (contains(p.reads, name) ? " (updated)" : ""),
                                describe(viewOf(*findResource(name)).desc)});
        report_.passes.push_back(std::move(r));
    };
    for (std::size_t i : order_)
        entry(i);
    for (std::size_t i = 0; i < passes_.size(); ++i)
        if (status_[i] == PassStatus::Culled)
            entry(i);
    return report_;
}

std::optional<PassStatus> FrameGraph::status(const PassId& pass) const {
    for (std::size_t i = 0; i < passes_.size() && i < status_.size(); ++i)
        if (passes_[i].id == pass)
            return status_[i];
    return std::nullopt;
}

GLuint FrameGraph::resourceId(std::string_view name) const {
    const Resource* r = findResource(name);
    return r ? viewOf(*r).id : 0;
}

std::optional<ResourceDesc> FrameGraph::resourceDesc(std::string_view name) const {
    const Resource* r = findResource(name);
    if (!r)
        return std::nullopt;
    return viewOf(*r).desc;
}

std::vector<std::string> FrameGraph::resourceNames() const {
    std::vector<std::string> names;
    for (const Resource& r : resources_)
        names.push_back(r.name);
    return names;
}

bool FrameGraph::produced(const PassId& pass) const {
    const std::optional<PassStatus> s = status(pass);
    return s && *s != PassStatus::Culled;
}

} // namespace lpv::renderer::graph
