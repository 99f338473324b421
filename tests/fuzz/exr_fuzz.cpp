// exr_fuzz.cpp: libFuzzer target for mcdtool's input path: the input bytes
// are written as input.exr and run through `mcdtool input.exr --median 3
// -o out.exr --memory-limit 256` in-process, so the header checks, channel
// discovery, guide extraction, filtering and writing all see hostile files.
// Invariants: the exit status is 0 or 1, and a failed run writes no out.exr.
#include "driver.h"
#include "fuzz_dir.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

mcdfuzz::FuzzDir* scratch = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    static mcdfuzz::FuzzDir dir("exr");
    scratch = &dir;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    scratch->reset();
    {
        std::ofstream out("input.exr", std::ios::binary);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    const int status = mcdtool::run_mcdtool(
        { "input.exr", "--median", "3", "-o", "out.exr", "--memory-limit", "256" });
    mcdfuzz::require(status == 0 || status == 1, "exit status is 0 or 1");
    mcdfuzz::require(status == 0 || !std::filesystem::exists("out.exr"), "a failed run wrote out.exr");
    scratch->leave();
    return 0;
}
