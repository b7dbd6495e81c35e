// The one command-line parser (tools/cli) every program shares: its syntax
// and its one error style, so the demo and the tools cannot drift apart.
#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"

#include <gtest/gtest.h>

using tessera::cli::CommandLine;

namespace {

struct Program {
    CommandLine line{"tessera-test", "A program to test the parser."};
    uint32_t width = 0;
    float level = 0.0f;
    std::string mode, out;
    bool quiet = false;
    std::vector<std::string> models;

    Program() {
        CLI::App& app = line.app();
        app.add_option("--width", width, "width")->type_name("N")->check(tessera::cli::count(16, 16384));
        app.add_option("--level", level, "level")->type_name("L")->check(tessera::cli::number(1, 64));
        app.add_option("--mode", mode, "mode")->type_name("M")->check(tessera::cli::oneOf({"a", "b", "c"}));
        app.add_option("--out", out, "out")->type_name("FILE")->check(tessera::cli::nonEmpty());
        app.add_option("--model", models, "repeatable")
            ->expected(1)
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        app.add_flag("--quiet", quiet, "quiet");
    }
    std::string error(std::vector<std::string> args) {
        auto parsed = line.parse(std::move(args));
        return parsed ? std::string("(parsed)") : parsed.error().message;
    }
};

} // namespace

TEST(CliCommandLine, BothSyntaxesReadTheSame) {
    Program a, b;
    ASSERT_TRUE(a.line.parse({"--width", "640", "--level", "2.5", "--mode", "b", "--quiet"}).value());
    ASSERT_TRUE(b.line.parse({"--width=640", "--level=2.5", "--mode=b", "--quiet"}).value());
    EXPECT_EQ(a.width, 640u);
    EXPECT_EQ(b.width, 640u);
    EXPECT_FLOAT_EQ(b.level, 2.5f);
    EXPECT_EQ(b.mode, "b");
    EXPECT_TRUE(a.quiet && b.quiet);
}

TEST(CliCommandLine, LastValueWinsAndRepeatableOptionsCollect) {
    Program p;
    ASSERT_TRUE(p.line.parse({"--width", "100", "--width", "200", "--model", "x.glb", "--model=y.obj"}).value());
    EXPECT_EQ(p.width, 200u);
    EXPECT_EQ(p.models, (std::vector<std::string>{"x.glb", "y.obj"}));
    EXPECT_EQ(Program().error({"--model", "x.glb", "y.obj"}), "unexpected argument \"y.obj\"; run with --help for the list");
}

TEST(CliCommandLine, ErrorsReadInOneStyle) {
    EXPECT_EQ(Program().error({"--width", "5"}), "--width expects a whole number from 16 to 16384, got \"5\"");
    EXPECT_EQ(Program().error({"--width=-3"}), "--width expects a whole number from 16 to 16384, got \"-3\"");
    EXPECT_EQ(Program().error({"--level", "nan"}), "--level expects a number from 1 to 64, got \"nan\"");
    EXPECT_EQ(Program().error({"--level", "1e40"}), "--level expects a number from 1 to 64, got \"1e40\"");
    EXPECT_EQ(Program().error({"--mode", "d"}), "--mode expects a, b or c, got \"d\"");
    EXPECT_EQ(Program().error({"--out="}), "--out needs a value");
    EXPECT_EQ(Program().error({"--width"}), "--width needs a value");
    EXPECT_EQ(Program().error({"--width", "--quiet"}), "--width needs a value");
    EXPECT_EQ(Program().error({"--out", "--width", "5"}), "--out needs a value");
    EXPECT_EQ(Program().error({"--quiet=1"}), "--quiet takes no value");
    EXPECT_EQ(Program().error({"--frobnicate"}), "unknown option \"--frobnicate\"; run with --help for the list");
}

TEST(CliCommandLine, HelpIsAFlagAndTheTextIsLaidOut) {
    Program p;
    auto parsed = p.line.parse({"--width", "640", "--help"});
    ASSERT_TRUE(parsed);
    EXPECT_FALSE(parsed.value());
    const std::string help = p.line.help();
    EXPECT_EQ(help.rfind("usage: tessera-test [options]\n\nA program to test the parser.\n", 0), 0u) << help;
    EXPECT_NE(help.find("  --width N             width\n"), std::string::npos) << help;
    EXPECT_NE(help.find("  --quiet               quiet\n"), std::string::npos) << help;
    for (size_t start = 0, end; (end = help.find('\n', start)) != std::string::npos; start = end + 1)
        EXPECT_LE(end - start, 79u) << help.substr(start, end - start);
}
