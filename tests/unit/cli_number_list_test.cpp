// The one reader of lists (tools/cli, NumberList.h): one set of number rules
// and one wording for every flag and input that takes a list, so the demo's
// --camera, --agents and --subdiv-level A:B cannot drift apart.
#include "tessera/cli/NumberList.h"

#include <gtest/gtest.h>

#include <cstdint>

using namespace tessera::cli;

namespace {

const ListForm kPose{"--pose", "x,y (2 numbers)", {"x", "y"}, 2, 2};
const ListForm kSizes{"--sizes", "whole numbers from 1 to 100", {}, 1, 8, ',', 1, 100};
const ListForm kSweep{"--level", "a number from 1 to 64", {}, 1, 2, ':', 1, 64};

template <class T>
std::string errorOf(std::string_view text, const ListForm& form) {
    auto parsed = parseNumberList<T>(text, form);
    return parsed ? std::string("(parsed)") : parsed.error().message;
}

} // namespace

TEST(CliNumberList, SplitsAtTheSeparatorAndTrimsSpacesAndTabs) {
    EXPECT_TRUE(splitList("").empty());
    EXPECT_EQ(splitList("a"), (std::vector<std::string_view>{"a"}));
    EXPECT_EQ(splitList(" a ,\tb,"), (std::vector<std::string_view>{"a", "b", ""}));
    EXPECT_EQ(splitList("1:2", ':'), (std::vector<std::string_view>{"1", "2"}));
    EXPECT_EQ(splitList(",,"), (std::vector<std::string_view>{"", "", ""}));
}

TEST(CliNumberList, ReadsDecimalNumbersWithOnePlusAndNoLocale) {
    auto pose = parseNumberList<float>(" +1.5 , -3e2 ", kPose);
    ASSERT_TRUE(pose) << pose.error().message;
    EXPECT_EQ(pose.value(), (std::vector<float>{1.5f, -300.0f}));
    auto sizes = parseNumberList<uint32_t>("1,+20,100", kSizes);
    ASSERT_TRUE(sizes) << sizes.error().message;
    EXPECT_EQ(sizes.value(), (std::vector<uint32_t>{1, 20, 100}));
    auto sweep = parseNumberList<float>("2:14.99", kSweep);
    ASSERT_TRUE(sweep) << sweep.error().message;
    EXPECT_EQ(sweep.value(), (std::vector<float>{2.0f, 14.99f}));
    auto one = parseNumber<double>("7", kSweep);
    ASSERT_TRUE(one);
    EXPECT_EQ(one.value(), 7.0);
}

TEST(CliNumberList, NamedItemsAreNamedInTheirMessages) {
    EXPECT_EQ(errorOf<float>("1", kPose), "--pose expects x,y (2 numbers), got \"1\"");
    EXPECT_EQ(errorOf<float>("1,2,3", kPose), "--pose expects x,y (2 numbers), got \"1,2,3\"");
    EXPECT_EQ(errorOf<float>("", kPose), "--pose expects x,y (2 numbers), got \"\"");
    EXPECT_EQ(errorOf<float>("1,", kPose), "--pose: y is missing in \"1,\" (expects x,y)");
    EXPECT_EQ(errorOf<float>("1,abc", kPose), "--pose: y = \"abc\" is not a number");
    EXPECT_EQ(errorOf<float>("0x10,1", kPose), "--pose: x = \"0x10\" is not a number");
    EXPECT_EQ(errorOf<float>("+-1,1", kPose), "--pose: x = \"+-1\" is not a number");
    EXPECT_EQ(errorOf<float>("+,1", kPose), "--pose: x = \"+\" is not a number");
    EXPECT_EQ(errorOf<float>("inf,1", kPose), "--pose: x = \"inf\" is not a finite number");
    EXPECT_EQ(errorOf<float>("1,1e60", kPose), "--pose: y = \"1e60\" is out of range");
    EXPECT_EQ(errorOf<double>("1,1e60", kPose), "(parsed)") << "1e60 fits a double";
    const ListForm bounded{"--pose", "x,y (2 numbers)", {"x", "y"}, 2, 2, ',', -90, 90};
    EXPECT_EQ(errorOf<float>("1,100", bounded), "--pose: y = \"100\" is not in [-90, 90]");
}

TEST(CliNumberList, AlikeItemsQuoteTheBadOneInTheListsOwnWords) {
    EXPECT_EQ(errorOf<uint32_t>("5,0", kSizes), "--sizes expects whole numbers from 1 to 100, got \"0\"");
    EXPECT_EQ(errorOf<uint32_t>("5,-1", kSizes), "--sizes expects whole numbers from 1 to 100, got \"-1\"");
    EXPECT_EQ(errorOf<uint32_t>("1.5", kSizes), "--sizes expects whole numbers from 1 to 100, got \"1.5\"");
    EXPECT_EQ(errorOf<uint32_t>("99999999999", kSizes),
              "--sizes expects whole numbers from 1 to 100, got \"99999999999\"");
    // An empty item quotes the whole list, where it can be seen.
    EXPECT_EQ(errorOf<uint32_t>("5,,6", kSizes), "--sizes expects whole numbers from 1 to 100, got \"5,,6\"");
    EXPECT_EQ(errorOf<uint32_t>("1,2,3,4,5,6,7,8,9", kSizes),
              "--sizes expects whole numbers from 1 to 100, got \"1,2,3,4,5,6,7,8,9\"");
    EXPECT_EQ(errorOf<float>("3:99", kSweep), "--level expects a number from 1 to 64, got \"99\"");
    EXPECT_EQ(errorOf<float>("nan", kSweep), "--level expects a number from 1 to 64, got \"nan\"");
    EXPECT_EQ(errorOf<float>("1:2:3", kSweep), "--level expects a number from 1 to 64, got \"1:2:3\"");
    EXPECT_EQ(expectedError(kSweep, "0").message, "--level expects a number from 1 to 64, got \"0\"");
    // Without a name (a CLI11 validator's message, which CLI11 prefixes).
    const ListForm unnamed{"", "a number from 1 to 64", {}, 1, 1, ',', 1, 64};
    EXPECT_EQ(errorOf<double>("65", unnamed), "expects a number from 1 to 64, got \"65\"");
}
