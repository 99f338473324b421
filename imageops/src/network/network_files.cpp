// network_files.cpp: the choice of weight files, the weights folder and the
// weights shared across runs (network_files.h).
#include "network/network_files.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

namespace mcdenoise {

namespace {

/// `base` with the suffix of `quality` where OIDN ships that size.
std::string sized(const std::string& base, NetworkQuality quality, bool has_small, bool has_large)
{
    if (quality == NetworkQuality::high && has_large)
        return base + "_large.tza";
    if (quality == NetworkQuality::fast && has_small)
        return base + "_small.tza";
    return base + ".tza";
}

bool is_folder(const std::string& path)
{
    std::error_code ec;
    return !path.empty() && std::filesystem::is_directory(path, ec);
}

}  // namespace

NetworkFiles choose_network_files(NetworkQuality quality, bool albedo, bool normal, bool prefilter)
{
    NetworkFiles files;
    normal = normal && albedo;
    if (albedo && normal)
        files.beauty = prefilter ? sized("rt_hdr_calb_cnrm", quality, true, true)
                                 : sized("rt_hdr_alb_nrm", quality, true, false);
    else if (albedo)
        files.beauty = sized("rt_hdr_alb", quality, true, false);
    else
        files.beauty = sized("rt_hdr", quality, true, false);
    if (prefilter && albedo)
        files.albedo_prefilter = sized("rt_alb", quality, false, true);
    if (prefilter && normal)
        files.normal_prefilter = sized("rt_nrm", quality, false, true);
    return files;
}

bool find_weights_dir(const std::string& requested, std::string& dir, std::string& error)
{
    if (!requested.empty()) {
        if (is_folder(requested)) {
            dir = requested;
            return true;
        }
        error = "the weights folder " + requested + " does not exist";
        return false;
    }
    const char* env         = std::getenv("MCD_WEIGHTS_DIR");
    const std::string env_dir = env ? env : "";
    for (const std::string& candidate : { env_dir, std::string(MCD_WEIGHTS_INSTALLED_DIR),
                                          std::string(MCD_WEIGHTS_BUILD_DIR) })
        if (is_folder(candidate)) {
            dir = candidate;
            return true;
        }
    error = "no weights folder: looked in $MCD_WEIGHTS_DIR ("
            + (env_dir.empty() ? std::string("unset") : env_dir) + "), " MCD_WEIGHTS_INSTALLED_DIR
            " and " MCD_WEIGHTS_BUILD_DIR "; run scripts/fetch-weights, or point MCD_WEIGHTS_DIR "
            "at a folder of OIDN 2.x rt_*.tza files";
    return false;
}

std::shared_ptr<const TensorMap> shared_weights(const std::string& path, std::string& error)
{
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const TensorMap>> loaded;
    std::lock_guard<std::mutex> lock(mutex);
    const auto found = loaded.find(path);
    if (found != loaded.end())
        return found->second;
    TensorMap tensors;
    if (!read_tza(path, tensors, error)) {
        error += " (run scripts/fetch-weights to install OIDN's weights again)";
        return nullptr;
    }
    auto shared = std::make_shared<const TensorMap>(std::move(tensors));
    loaded[path] = shared;
    return shared;
}

}  // namespace mcdenoise
