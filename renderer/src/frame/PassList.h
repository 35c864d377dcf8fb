#pragma once
// The frame's pass table as a list of pass types (PassTable.cpp holds the
// one list): build() creates each pass into the renderer's table, and
// addOutputs() and addNames() collect, without creating anything, the names a pass type
// declares in its own header, so `lpv render --dump` can check a name
// before a frame exists:
//   - `static constexpr std::string_view kName`: its name (GraphPass(kName));
//   - `static constexpr std::array kOutputs{...}`: the handles it alone writes.
// A type is created with its static create() (a pass that builds shaders and
// may fail, or that makes several passes) when it has one, else with new.
#include "frame/FramePass.h"
#include "lpv/scene/Error.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lpv::renderer {

// Adds created passes to the table; the first that could not be created
// (a shader error) is remembered, and finish() returns it.
class PassTableBuilder {
  public:
    explicit PassTableBuilder(std::vector<std::unique_ptr<FramePass>>& table) : table_(table) {}
    template <typename Pass> void add(std::unique_ptr<Pass> pass) { table_.push_back(std::move(pass)); }
    template <typename Pass> void add(std::vector<std::unique_ptr<Pass>> passes) {
        for (std::unique_ptr<Pass>& pass : passes)
            add(std::move(pass));
    }
    template <typename Created> void add(scene::Expected<Created> created) {
        if (created)
            add(std::move(*created));
        else if (!error_)
            error_ = created.error();
    }
    scene::Expected<void> finish() const {
        if (error_)
            return std::unexpected(*error_);
        return {};
    }

  private:
    std::vector<std::unique_ptr<FramePass>>& table_;
    std::optional<scene::Error> error_;
};

template <typename... Passes> struct PassList {
    static scene::Expected<void> build(std::vector<std::unique_ptr<FramePass>>& table) {
        PassTableBuilder builder(table);
        (builder.add(create<Passes>()), ...);
        return builder.finish();
    }
    static void addOutputs(std::vector<std::string>& names) { (addOutputsOf<Passes>(names), ...); }
    static void addNames(std::vector<std::string>& names) { (addNameOf<Passes>(names), ...); }

  private:
    template <typename Pass> static auto create() {
        if constexpr (requires { Pass::create(); })
            return Pass::create();
        else
            return std::make_unique<Pass>();
    }
    template <typename Pass> static void addOutputsOf(std::vector<std::string>& names) {
        if constexpr (requires { Pass::kOutputs; })
            for (graph::ResourceHandle output : Pass::kOutputs)
                names.push_back(output.str());
    }
    template <typename Pass> static void addNameOf(std::vector<std::string>& names) {
        if constexpr (requires { Pass::kName; })
            names.emplace_back(Pass::kName);
    }
};

// A pass of the table the renderer keeps a typed view of (read-backs,
// counters): the first of that type, or null.
template <typename Pass> Pass* findPass(const std::vector<std::unique_ptr<FramePass>>& table) {
    for (const std::unique_ptr<FramePass>& pass : table)
        if (auto* typed = dynamic_cast<Pass*>(pass.get()))
            return typed;
    return nullptr;
}

} // namespace lpv::renderer
