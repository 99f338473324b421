// test_cpu_check.cpp: the load-time CPU check's decision, with injected
// feature sets: what is missing is found and named, nothing is reported on
// a CPU that has everything, and the build's list follows its -march.
#include "core/cpu_check.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

using mcdenoise::build_cpu_features;
using mcdenoise::missing_cpu_features;

/// A CPU with SSE up to 4.2, POPCNT and AVX, but not AVX2, FMA or BMI (a
/// Sandy Bridge).
bool sandy_bridge(const char* name)
{
    for (const char* has : { "sse3", "ssse3", "sse4.1", "sse4.2", "popcnt", "avx" })
        if (std::strcmp(name, has) == 0)
            return true;
    return false;
}

bool every_feature(const char*) { return true; }

const char* const x86_64_v3[] = { "sse3", "ssse3", "sse4.1", "sse4.2", "popcnt", "avx",
                                  "avx2", "fma",   "bmi",    "bmi2",   nullptr };

TEST(CpuCheck, NamesEveryMissingFeature)
{
    char missing[64];
    EXPECT_EQ(missing_cpu_features(x86_64_v3, sandy_bridge, missing, sizeof missing), 4);
    EXPECT_STREQ(missing, "avx2 fma bmi bmi2");
}

TEST(CpuCheck, PassesACpuWithEveryFeature)
{
    char missing[64] = "stale";
    EXPECT_EQ(missing_cpu_features(x86_64_v3, every_feature, missing, sizeof missing), 0);
    EXPECT_STREQ(missing, "");
    const char* const none[] = { nullptr };
    EXPECT_EQ(missing_cpu_features(none, sandy_bridge, missing, sizeof missing), 0);
}

TEST(CpuCheck, CountsNamesThatDoNotFit)
{
    char missing[9];
    EXPECT_EQ(missing_cpu_features(x86_64_v3, sandy_bridge, missing, sizeof missing), 4);
    EXPECT_STREQ(missing, "avx2 fma");
}

TEST(CpuCheck, BuildListFollowsTheCompilerFlags)
{
    // This test is compiled with the library's flags, so the compiler's
    // macros here say what the library needs.
    std::string listed;
    for (const char* const* name = build_cpu_features; *name; ++name)
        listed += std::string(" ") + *name + " ";
#ifdef __AVX2__
    EXPECT_NE(listed.find(" avx2 "), std::string::npos) << listed;
#else
    EXPECT_EQ(listed.find(" avx2 "), std::string::npos) << listed;
#endif
    // This process runs, so the CPU has what the build needs.
    char missing[256];
    EXPECT_EQ(missing_cpu_features(build_cpu_features, mcdenoise::running_cpu_supports, missing,
                                   sizeof missing),
              0)
        << missing;
}

}  // namespace
