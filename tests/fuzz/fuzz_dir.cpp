// fuzz_dir.cpp: the scratch directory and the invariant check.
#include "fuzz_dir.h"

#include <sanitizer/common_interface_defs.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace mcdfuzz {

namespace fs = std::filesystem;

FuzzDir::FuzzDir(const std::string& target)
{
    const char* tmp = std::getenv("TMPDIR");
    fs::path base = tmp && *tmp ? fs::path(tmp) : fs::path("/tmp");
    path_ = (base / ("mcd-fuzz-" + target + "-" + std::to_string(getpid()))).string();
    home_ = fs::current_path().string();
    fs::remove_all(path_);
    fs::create_directories(path_);
}

FuzzDir::~FuzzDir()
{
    std::error_code error;
    fs::current_path(home_, error);
    fs::remove_all(path_, error);
}

void FuzzDir::add(const std::string& name, std::string bytes) { files_[name] = std::move(bytes); }

void FuzzDir::reset() const
{
    std::error_code error;
    fs::current_path(path_, error);
    for (const fs::directory_entry& entry : fs::directory_iterator(path_, error))
        fs::remove_all(entry.path(), error);
    for (const auto& [name, bytes] : files_) {
        std::ofstream out(fs::path(path_) / name, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }
}

void FuzzDir::leave() const
{
    std::error_code error;
    fs::current_path(home_, error);
}

std::string file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void require(bool ok, const std::string& what)
{
    if (ok)
        return;
    // Through the sanitizer's report channel: libFuzzer's -close_fd_mask
    // closes the target's own stderr but keeps that one.
    __sanitizer_report_error_summary(("mcdfuzz: invariant broken: " + what).c_str());
    std::abort();
}

}  // namespace mcdfuzz
