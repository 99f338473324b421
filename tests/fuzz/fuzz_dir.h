// fuzz_dir.h: what the fuzz targets share: a private scratch directory,
// laid out afresh for every input (the files registered at start-up written
// back, anything a run left removed), and a check that stops the fuzzer with
// a message when an invariant breaks.
#pragma once

#include <map>
#include <string>

namespace mcdfuzz {

/// A scratch directory under $TMPDIR (or /tmp) named after the target and
/// the process, removed at exit. The process works inside it between
/// reset() and leave(), so libFuzzer's relative paths stay valid outside.
class FuzzDir {
public:
    explicit FuzzDir(const std::string& target);
    FuzzDir(const FuzzDir&) = delete;
    FuzzDir& operator=(const FuzzDir&) = delete;
    ~FuzzDir();

    /// Registers a file written back by every reset().
    void add(const std::string& name, std::string bytes);
    /// Empties the directory, writes the registered files and enters it.
    void reset() const;
    /// Returns to the directory the process started in.
    void leave() const;
    /// The directory's absolute path.
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::string home_;
    std::map<std::string, std::string> files_;
};

/// The bytes of the file at `path` (empty if it cannot be read).
std::string file_bytes(const std::string& path);

/// Stops the process (a crash the fuzzer records) with `what` if `ok` is false.
void require(bool ok, const std::string& what);

}  // namespace mcdfuzz
