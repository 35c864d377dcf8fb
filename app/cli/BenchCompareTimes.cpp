// `lpv bench compare-times A.json B.json`: whether two timings of the same
// settings (a report run twice: OUT1/NAME/timing.json, OUT2/NAME/timing.json)
// give the same ranking, issue #43's check that the times can be trusted.
#include "BenchReport.h"
#include "Cli.h"

#include "lpv/bench/SharedTiming.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

void printBenchCompareTimesHelp() {
    std::cout << R"(
bench compare-times A.json B.json: two timings of the same settings
(`lpv bench report` writes one per scene, OUT/NAME/timing.json) side by
side: how many settings both have, the Spearman rank correlation of their
medians, of all of them and of those whose times differ by more than the
noise (from the cheapest up, each a different cost from every one kept, in
both runs: the order of settings of the same cost is noise), the pairs of
settings both call different costs and how many of them the two order
oppositely, how many settings have the same cost in both runs, the largest
ratio of one setting's two medians, and the median spread. Exit 0 when the
ranking agrees (Spearman of the distinct settings >= 0.95 and no pair
ordered oppositely), 1 when it does not.
)";
}

int benchCompareTimes(Args args) {
    const auto pos = args.expectPositionals(2, "bench compare-times expects two timing files (OUT/NAME/timing.json)", 1); // after "compare-times"
    if (pos.empty())
        return usageError(*args.error(), "bench");
    const auto a = bench::loadSharedTiming(pos[0]);
    const auto b = bench::loadSharedTiming(pos[1]);
    for (const auto* t : {&a, &b})
        if (!*t) {
            std::cerr << "lpv: " << t->error().describe() << "\n";
            return kFailure;
        }
    const bench::TimingAgreement g = bench::compareTimings(*a, *b);
    std::printf("A: %s\n   %d rounds (%s), %s\n", pos[0].c_str(), a->rounds, a->stopReason.c_str(), a->load.c_str());
    std::printf("B: %s\n   %d rounds (%s), %s\n", pos[1].c_str(), b->rounds, b->stopReason.c_str(), b->load.c_str());
    std::printf("settings in both:                         %d\n", g.settings);
    std::printf("Spearman rank correlation of the medians: %.3f\n", g.spearman);
    std::printf("  of the %2d settings apart by more than the noise: %.3f\n", g.distinctSettings,
                g.distinctSpearman);
    std::printf("pairs both call different costs:          %d, ordered oppositely: %d\n", g.distinctPairs,
                g.discordantPairs);
    std::printf("settings of the same cost in A and B:     %d of %d\n", g.sameCostInBoth, g.settings);
    std::printf("largest ratio of one setting's medians:   %.2fx (%s)\n", g.largestRatio,
                g.largestRatioSetting.c_str());
    std::printf("median spread (IQR / median):             %.1f%%\n", 100.0 * g.medianSpread);
    const bool agrees = bench::rankingAgrees(g);
    std::printf("%s\n", agrees ? "the ranking agrees" : "the ranking does NOT agree");
    return agrees ? kOk : kFailure;
}

} // namespace lpv::cli
