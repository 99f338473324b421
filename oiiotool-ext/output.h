// output.h: writing like a compositing step. The output keeps every input
// channel and the input's metadata with only the beauty channels replaced,
// in the input's pixel types and compression unless -d / --compression say
// otherwise. Every file of a frame is written to a temp file in its own
// directory and renamed into place only when the whole frame succeeded, so
// a failure leaves no output behind; an interrupted run removes its temp
// files (cleanup.h). A replaced file keeps its mode; messages name the
// final path, never the temp file.
#pragma once

#include "input.h"
#include "options.h"
#include "runstats.h"

#include <OpenImageIO/imagebuf.h>

#include <map>
#include <string>
#include <vector>

namespace mcdtool {

using OIIO::ImageBuf;
using OIIO::ImageSpec;

/// The files of one frame, written to temp names and renamed together.
class OutputBatch {
public:
    explicit OutputBatch(RunStats& stats) : stats_(stats) {}
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    /// Removes any temp file not committed.
    ~OutputBatch();

    /// Writes `pixels` (float, `spec.nchannels` channels covering the data
    /// window of `spec`) to a temp file beside `path`, the channels of
    /// `stored` from its images instead (in their own pixel type, when the
    /// format keeps per-channel types). Throws RunError
    /// "<context> : cannot write '<path>': <reason>".
    void write(const std::string& path, const ImageSpec& spec, const ImageBuf& pixels,
               const std::string& context, const std::map<int, ImageBuf>& stored = {});
    /// Writes the parts `specs` of a multi-part file, part p's float pixels
    /// from `pixels[p]`, as `write` does.
    void write_parts(const std::string& path, const std::vector<ImageSpec>& specs,
                     const std::vector<ImageBuf>& pixels, const std::string& context);
    /// Renames every temp file into place. Throws RunError on failure.
    void commit();

private:
    /// Creates the writer of a temp file beside `path`, tracks the file,
    /// calls `fill(out, temp, fail)` to open and write it, closes it and
    /// times it all; `fail(reason)` is the RunError to throw.
    template<class Fill>
    void write_temp(const std::string& path, const std::string& context, Fill&& fill);

    /// A temp file written and not yet renamed.
    struct Pending {
        std::string temp, final_path;
        int slot;  ///< in the interrupt cleanup table
    };
    RunStats& stats_;
    std::vector<Pending> pending_;
};

/// Applies `format` to `spec`: -d sets every channel's pixel type,
/// --compression the compression attribute; empty fields leave them.
void apply_format(ImageSpec& spec, const OutputFormat& format);

/// What one -o writes: the file spec and its float pixels.
struct OutputImage {
    ImageSpec spec;
    ImageBuf pixels;
    /// Channels written from their stored values instead: integers of 32
    /// bits (an Arnold ID pass), which float pixels cannot carry exactly.
    std::map<int, ImageBuf> stored;
    bool beauty_only = false;  ///< the format could not hold every channel by name
};

/// The output for `path`: the input with channels `beauty` replaced by the
/// channels of `result` (same data window), in the spec of the input file
/// (channels, per-channel pixel types, metadata, compression, data and
/// display windows) with `format` applied; channels the input stores as
/// 32-bit integers (`integers`, the input's) pass through exactly. A format that holds at
/// most four channels (PNG, JPEG) or does not store channel names (TIFF,
/// DPX: the AOVs would come back as "channel4", ...) gets the beauty
/// channels only.
OutputImage compose_output(const ImageBuf& input, const IntegerChannels& integers, const std::vector<int>& beauty,
                           const ImageBuf& result, const OutputFormat& format, const std::string& path);

/// Makes `path` ready to be written by `option` ("-o", "--preview") before
/// any work: its folder is created if missing (as renderers do), and an
/// existing file whose mode forbids writing (e.g. 0444) is refused unless
/// `force`. Throws RunError "<option> : ..." naming `path`.
void prepare_output_path(const std::string& option, const std::string& path, bool force);

/// True if `a` and `b` name the same file (or would, once `b` exists).
bool same_file(const std::string& a, const std::string& b);

}  // namespace mcdtool
