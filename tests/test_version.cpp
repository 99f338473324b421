// test_version.cpp: the version is one: the macros of mcdenoise/version.h,
// the loaded library's `version()` and `version_number()`, and the project
// version CMake read from the header (MCD_PROJECT_VERSION, passed by the
// build) agree.
#include <mcdenoise/version.h>

#include <gtest/gtest.h>

#include <string>

TEST(Version, TheLoadedLibraryReportsTheHeadersVersion)
{
    EXPECT_STREQ(mcdenoise::version(), MCDENOISE_VERSION_STRING);
    EXPECT_EQ(mcdenoise::version_number(), MCDENOISE_VERSION);
}

TEST(Version, TheStringAndTheNumbersAgree)
{
    const std::string parts = std::to_string(MCDENOISE_VERSION_MAJOR) + "."
                              + std::to_string(MCDENOISE_VERSION_MINOR) + "."
                              + std::to_string(MCDENOISE_VERSION_PATCH);
    EXPECT_EQ(parts, MCDENOISE_VERSION_STRING);
    EXPECT_EQ(MCDENOISE_VERSION, MCDENOISE_VERSION_MAJOR * 10000 + MCDENOISE_VERSION_MINOR * 100
                                     + MCDENOISE_VERSION_PATCH);
}

TEST(Version, CMakesProjectVersionIsTheHeaders)
{
    EXPECT_STREQ(MCD_PROJECT_VERSION, MCDENOISE_VERSION_STRING);
}
