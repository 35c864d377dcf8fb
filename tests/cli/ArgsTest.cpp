// The command line reader every `lpv` command parses with (app/cli/Args.h),
// called directly: typed options convert and range-check their values, and
// every bad value is said the one way ("--opt: 'x' is not ..."), the first
// problem kept, so the commands need no number parsing of their own.
#include "Args.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv::cli;

namespace {

Args argsOf(std::vector<std::string> words) {
    return Args(std::move(words));
}

TEST(Args, WholeNumbersInTheirRangeOrTheFallbackAndOneMessage) {
    Args args = argsOf({"PROJECT", "--width", "640", "--height=abc", "--crf", "60"});
    EXPECT_EQ(args.integer("--width", 320, {1}), 640);
    EXPECT_EQ(args.integer("--height", 180, {1}), 180) << "a bad value gives the fallback";
    EXPECT_EQ(args.integer("--crf", 18, {0, 51}), 18);
    EXPECT_EQ(args.integer("--frames", 20, {1}), 20) << "absent";
    EXPECT_EQ(args.error(), "--height: 'abc' is not a whole number of 1 or more") << "the first problem";
    EXPECT_EQ(args.positionals(), (std::vector<std::string>{"PROJECT"}));

    Args crf = argsOf({"--crf", "60"});
    EXPECT_FALSE(crf.optionalInteger("--crf", {0, 51}));
    EXPECT_EQ(crf.error(), "--crf: '60' is not a whole number from 0 to 51");
    Args negative = argsOf({"--cascade", "-1", "--slice", "-2"});
    EXPECT_FALSE(negative.optionalInteger("--cascade", {0}));
    EXPECT_EQ(negative.optionalInteger("--slice"), -2) << "a negative value is a value, not an option";
    EXPECT_EQ(negative.error(), "--cascade: '-1' is not a whole number of 0 or more");
    for (const char* bad : {"1.5", "", "2x", " 3", "99999999999"}) {
        Args a = argsOf({"--n", bad});
        EXPECT_FALSE(a.optionalInteger("--n")) << bad;
        EXPECT_EQ(a.error(), std::string("--n: '") + bad + "' is not a whole number") << bad;
    }
}

TEST(Args, RealNumbersAreFiniteAndInTheirRange) {
    EXPECT_EQ(RealRange::above(0.0).describe(), "a finite number above 0");
    EXPECT_EQ(RealRange::atLeast(0.0).describe(), "a finite number of 0 or more");
    EXPECT_EQ((RealRange{0.0, 1.0, true, false}).describe(), "a number in (0, 1]");
    EXPECT_EQ((RealRange{0.0, 1.0}).describe(), "a number in [0, 1]");
    EXPECT_EQ(RealRange{}.describe(), "a finite number");
    for (const char* bad : {"0", "-1", "nan", "inf", "1e400", "abc", "2x", ""}) {
        Args a = argsOf({"--scale", bad});
        EXPECT_FALSE(a.optionalReal("--scale", RealRange::above(0.0))) << bad;
        EXPECT_EQ(a.error(), std::string("--scale: '") + bad + "' is not a finite number above 0") << bad;
    }
    Args a = argsOf({"--residual", "1", "--ppd=67.5", "--turn", "1e-3"});
    EXPECT_DOUBLE_EQ(*a.optionalReal("--residual", {0.0, 1.0, true, false}), 1.0)
        << "a closed end includes it";
    EXPECT_DOUBLE_EQ(a.real("--ppd", 30.0, RealRange::above(0.0)), 67.5);
    std::string given;
    EXPECT_DOUBLE_EQ(*a.optionalReal("--turn", {0.0, 180.0, true, false}, &given), 0.001);
    EXPECT_EQ(given, "1e-3") << "the text as typed, for commands that echo it";
    EXPECT_FALSE(a.error());
}

TEST(Args, ListsChoicesShardsAndPaths) {
    Args a = argsOf({"--tiles", "32,64,1024", "--steps", "1,,2", "--direction", "0,1,0", "--axis", "y",
                     "--shard", "1/4", "--out", "dir/x"});
    EXPECT_EQ(a.integerList("--tiles", {32, 1024}), (std::vector<int>{32, 64, 1024}));
    EXPECT_FALSE(a.integerList("--steps", {0, 64})) << "an empty item";
    EXPECT_EQ(a.realList("--direction", 3), (std::vector<double>{0.0, 1.0, 0.0}));
    EXPECT_EQ(a.choice("--axis", {"x", "y", "z"}), "y");
    EXPECT_EQ(a.shard("--shard"), (lpv::reference::ShardSpec{1, 4}));
    EXPECT_EQ(a.path("--out"), std::filesystem::path("dir/x"));
    EXPECT_FALSE(a.integerList("--absent", {0, 64})) << "absent: the caller's default";
    EXPECT_EQ(a.error(), "--steps: '1,,2' is not a comma-separated list, each a whole number from 0 to 64");

    Args direction = argsOf({"--direction", "1,2"});
    EXPECT_FALSE(direction.realList("--direction", 3));
    EXPECT_EQ(direction.error(), "--direction: '1,2' is not 3 comma-separated numbers");
    Args axis = argsOf({"--axis", "w"});
    EXPECT_FALSE(axis.choice("--axis", {"x", "y", "z"}));
    EXPECT_EQ(axis.error(), "--axis: 'w' is not x, y or z");
    Args shard = argsOf({"--shard", "4/4"});
    EXPECT_FALSE(shard.shard("--shard"));
    EXPECT_EQ(shard.error(),
              "--shard: '4/4' is not I/N with 0 <= I < N (e.g. 0/4: the first of four shards)");
}

TEST(Args, BadValuesComeBeforeMissingValuesAndUnknownOptions) {
    Args a = argsOf({"--frames", "0", "--bogus", "--camera"});
    EXPECT_EQ(a.integer("--frames", 5, {1}), 5);
    EXPECT_FALSE(a.option("--camera"));
    EXPECT_EQ(a.error(), "--frames: '0' is not a whole number of 1 or more");
    Args missing = argsOf({"--bogus", "--camera"});
    EXPECT_FALSE(missing.option("--camera"));
    EXPECT_EQ(missing.error(), "--camera needs a value");
    Args unknown = argsOf({"--bogus"});
    EXPECT_EQ(unknown.error(), "unknown option '--bogus'");
    Args sound = argsOf({"FILE", "--camera", "front"});
    EXPECT_EQ(sound.option("--camera"), "front");
    EXPECT_FALSE(sound.error());
}

TEST(Args, PositionalsAreCheckedAfterTheOptionsAndBeforeRequiredOptions) {
    Args sound = argsOf({"lpv", "PROJECT", "-o", "out.png"});
    const auto output = sound.option("--output", "-o");
    sound.require(output.has_value(), "missing -o OUT.png");
    EXPECT_EQ(sound.expectPositionals(1, "expected exactly one project file", 1),
              (std::vector<std::string>{"PROJECT"}))
        << "after the subcommand";
    EXPECT_FALSE(sound.error());

    Args twoFiles = argsOf({"A", "B"});
    twoFiles.require(false, "missing -o OUT.png");
    EXPECT_TRUE(twoFiles.expectPositionals(1, "expected exactly one project file").empty());
    EXPECT_EQ(twoFiles.error(), "expected exactly one project file") << "the files first";

    Args noOutput = argsOf({"A"});
    noOutput.require(false, "missing -o OUT.png");
    noOutput.require(false, "missing --what VIEW");
    EXPECT_TRUE(noOutput.expectPositionals(1, "expected exactly one project file").empty());
    EXPECT_EQ(noOutput.error(), "missing -o OUT.png") << "the first required option missing";

    Args badValue = argsOf({"A", "B", "--width", "0"});
    EXPECT_EQ(badValue.integer("--width", 1, {1}), 1);
    EXPECT_TRUE(badValue.expectPositionals(1, "expected exactly one project file").empty());
    EXPECT_EQ(badValue.error(), "--width: '0' is not a whole number of 1 or more") << "the options first";
}

TEST(Args, TheShortFormWinsAndARejectedValueIsSaidTheSameWay) {
    Args a = argsOf({"-o", "short.png", "--output", "long.png"});
    EXPECT_EQ(a.option("--output", "-o"), "short.png");
    Args b = argsOf({"--output=long.png"});
    EXPECT_EQ(b.option("--output", "-o"), "long.png");
    b.reject("--unit", "km", "one of mm, cm, m");
    b.reject("--unit", "mi", "one of mm, cm, m");
    EXPECT_EQ(b.error(), "--unit: 'km' is not one of mm, cm, m") << "the first rejection is kept";
}

} // namespace
