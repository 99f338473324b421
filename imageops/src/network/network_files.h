// network_files.h: which of OIDN's weight files a denoise runs (by quality
// and by the guides present, as OIDN 2.4's RT filter picks them), where the
// weights folder is, and the weights read once per process and shared;
// implemented in network_files.cpp.
#pragma once

#include "network/tza.h"

#include <mcdenoise/denoise_network.h>

#include <memory>
#include <string>

namespace mcdenoise {

/// The weight files of one denoise, by file name ("rt_hdr_calb_cnrm_large.tza");
/// the prefilters' are empty when the guide is absent or not prefiltered.
struct NetworkFiles {
    std::string beauty;
    std::string albedo_prefilter;
    std::string normal_prefilter;
};

/// The files for `quality` with the guides present: the beauty's network
/// by guides (`rt_hdr`, `rt_hdr_alb`, `rt_hdr_alb_nrm`, or with
/// `prefilter` and both guides `rt_hdr_calb_cnrm`), `_large` for high and
/// `_small` for fast where OIDN ships one; the prefilters `rt_alb`,
/// `rt_nrm` (`_large` for high) when `prefilter` and the guide is present.
/// A normal without an albedo is not used.
NetworkFiles choose_network_files(NetworkQuality quality, bool albedo, bool normal, bool prefilter);

/// The weights folder for `requested` (NetworkOptions::weights_dir): that
/// folder when not empty, else $MCD_WEIGHTS_DIR, else the installed
/// weights (share/mcdenoise/weights of the install prefix), else the build
/// tree's; the first that exists. False with `error` naming the places
/// looked in and the fix when none does.
bool find_weights_dir(const std::string& requested, std::string& dir, std::string& error);

/// The tensors of the weight file `path`, read on first use and shared
/// after; null with `error` naming the file and the fix when it is
/// missing, truncated or corrupt.
std::shared_ptr<const TensorMap> shared_weights(const std::string& path, std::string& error);

}  // namespace mcdenoise
