#pragma once
// Shared pieces of the `lpv` command-line tool: exit codes, the argument
// reader (Args.h) and the commands. Each command lives in its own file and
// calls the libraries.
#include "Args.h"

#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

enum ExitCode : int { kOk = 0, kFailure = 1, kUsage = 2 };

int usageError(const std::string& message, const std::string& command);

// A loaded project's warnings (scene::Project::loadWarnings) on stderr, each
// prefixed with the file: the first 20, then how many more.
void printLoadWarnings(const std::string& projectFile, const std::vector<std::string>& warnings);

int runRender(Args args);
int runParams(Args args);
int runNew(Args args);
int runInfo(Args args);
int runImport(Args args);
int runBench(Args args);
int runVersion(); // `lpv --version`, in VersionCommand.cpp
int runVideo(Args args);
int runPath(Args args);
int runRadiosity(Args args); // `lpv radiosity`, in RadiosityCommand.cpp
// `lpv radiosity` as a function of its options (what `lpv bench report` runs).
struct RadiosityCommand {
    std::string projectFile;
    std::optional<std::string> output, imageFile, cameraName, hemicubeFile;
    std::optional<double> residual; // else radiosity.convergenceThreshold
    std::optional<double> refine;
    double maxSeconds = 0.0;        // 0: no limit
    double progressInterval = 1.0;
    int width = 800, height = 600;
    std::string view = "radiosity"; // radiosity, ambient, unshot, shot
    bool restart = false, wireframe = false, useCpu = false;
    std::vector<std::string> sets;
};
int runRadiosityCommand(const RadiosityCommand& command);
int runReference(Args args); // `lpv reference`, in ReferenceCommand.cpp
int runCompare(Args args);   // `lpv compare`, in CompareCommand.cpp
int runMerge(Args args);     // `lpv merge`, in MergeCommand.cpp
int runDump(Args args); // `lpv dump`, in DumpCommand.cpp
int benchRender(Args args); // `lpv bench render`, in BenchRenderCommand.cpp
int benchLpv(Args args);    // `lpv bench lpv`, in BenchLpvCommand.cpp
int benchPack(Args args);   // `lpv bench pack`, in BenchPackCommand.cpp
int benchSweep(Args args);  // `lpv bench PROJECT --sweep`, in BenchSweepCommand.cpp
int benchAccuracyReport(Args args); // `lpv bench report`, in BenchAccuracyReport.cpp
int benchCompareTimes(Args args);   // `lpv bench compare-times`, in BenchCompareTimes.cpp
void printBenchCompareTimesHelp();
int benchFlicker(Args args); // `lpv bench PROJECT --flicker`, in BenchFlickerCommand.cpp
int benchMerge(Args args);   // `lpv bench merge OUT_DIR SHARD_DIR...`, in BenchMergeCommand.cpp
void printBenchMergeHelp();

void printRenderHelp();
void printParamsHelp();
void printNewHelp();
void printInfoHelp();
void printImportHelp();
void printBenchHelp();
void printVideoHelp();
void printPathHelp();
void printRadiosityHelp();
void printReferenceHelp();
void printCompareHelp();
void printMergeHelp();
void printDumpHelp();

} // namespace lpv::cli
