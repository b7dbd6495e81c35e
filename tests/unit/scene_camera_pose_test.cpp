// A camera pose's text form: the engine writes it (scene::formatCameraPose),
// the command line reads it (cli::parseCameraPose, by the one list reader).
#include "tessera/cli/CameraPoseText.h"
#include "tessera/scene/CameraPose.h"

#include <gtest/gtest.h>

using tessera::cli::parseCameraPose;
using tessera::scene::CameraPose;
using tessera::scene::formatCameraPose;

namespace {

/// The error message for `text`, or "" when it parsed.
std::string errorFor(std::string_view text) {
    auto result = parseCameraPose(text);
    return result ? std::string() : result.error().message;
}

} // namespace

TEST(SceneCameraPose, ParsesFiveNumbersWithDegrees) {
    auto pose = parseCameraPose("1.5,-2,3e2,90,-45");
    ASSERT_TRUE(pose) << pose.error().message;
    EXPECT_EQ(pose->position, glm::vec3(1.5f, -2.0f, 300.0f));
    EXPECT_FLOAT_EQ(pose->yaw, glm::radians(90.0f));
    EXPECT_FLOAT_EQ(pose->pitch, glm::radians(-45.0f));
}

TEST(SceneCameraPose, AllowsSpacesAndPlusSigns) {
    auto pose = parseCameraPose(" 1 , 2,\t3 ,+180, 0 ");
    ASSERT_TRUE(pose) << pose.error().message;
    EXPECT_EQ(pose->position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(pose->yaw, glm::radians(180.0f));
    EXPECT_EQ(pose->pitch, 0.0f);
}

TEST(SceneCameraPose, RejectsWrongCount) {
    EXPECT_EQ(errorFor("1,2"), "--camera expects x,y,z,yaw,pitch (5 numbers), got \"1,2\"");
    EXPECT_NE(errorFor(""), "");
    EXPECT_NE(errorFor("1,2,3,4"), "");
    EXPECT_NE(errorFor("1,2,3,4,5,6"), "");
    EXPECT_NE(errorFor("1,2,3,4,5,"), "");
}

TEST(SceneCameraPose, RejectsNonNumbers) {
    EXPECT_EQ(errorFor("1,abc,3,4,5"), "--camera: y = \"abc\" is not a number");
    EXPECT_NE(errorFor("1,2,,4,5").find("z is missing"), std::string::npos);
    EXPECT_NE(errorFor("1,2,3,4,5x").find("pitch"), std::string::npos); // Trailing junk.
    EXPECT_NE(errorFor("1,2,3,4 5,5"), "");                              // Inner space.
    EXPECT_NE(errorFor("1,2,3,0x10,5"), "");
    EXPECT_NE(errorFor("1,2,3,+,5"), "");
    EXPECT_NE(errorFor("1,2,3,+-4,5"), "");
    EXPECT_NE(errorFor("1;2;3;4;5"), "");
}

TEST(SceneCameraPose, RejectsNonFinite) {
    EXPECT_EQ(errorFor("nan,2,3,4,5"), "--camera: x = \"nan\" is not a finite number");
    EXPECT_NE(errorFor("1,inf,3,4,5").find("not a finite number"), std::string::npos);
    EXPECT_NE(errorFor("1,2,-infinity,4,5").find("not a finite number"), std::string::npos);
    EXPECT_NE(errorFor("1,2,3,1e60,5").find("out of range"), std::string::npos);
}

TEST(SceneCameraPose, FormatRoundTrips) {
    CameraPose pose{glm::vec3(12.25f, -3.5f, 1000.0f), glm::radians(33.0f), glm::radians(-20.0f)};
    std::string text = formatCameraPose(pose);
    auto parsed = parseCameraPose(text);
    ASSERT_TRUE(parsed) << text;
    EXPECT_EQ(parsed->position, pose.position);
    EXPECT_NEAR(parsed->yaw, pose.yaw, 1e-6f);
    EXPECT_NEAR(parsed->pitch, pose.pitch, 1e-6f);
}
