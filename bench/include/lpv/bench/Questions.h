#pragma once
// The questions `lpv bench report` asks of every scene, each one key swept
// around the project's settings ("what do more propagation steps buy?"); the
// editor's sweep dock offers the same ones by default.
#include <string>
#include <vector>

namespace lpv::bench {

struct Question {
    std::string name;       // "steps"
    std::string sweep;      // "KEY=V1,V2,...": the full report
    std::string quickSweep; // `lpv bench report --quick`; empty = left out
};

const std::vector<Question>& reportQuestions();

} // namespace lpv::bench
