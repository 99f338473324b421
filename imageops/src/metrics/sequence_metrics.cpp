// sequence_metrics.cpp: per-frame relMSE, temporal error and flicker of a
// frame sequence, accumulated frame by frame. Per-value running sums are
// updated in parallel over rows (each value by one thread); the totals are
// per-row partial sums added in row order, so results do not depend on the
// threads.
#include <mcdenoise/sequence_metrics.h>

#include <OpenImageIO/imagebufalgo_util.h>
#include <OpenImageIO/strutil.h>

#include <cmath>
#include <limits>

namespace mcdenoise {

namespace {

using OIIO::Strutil::fmt::format;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

/// A sum and the number of values in it.
struct Total {
    double sum = 0;
    double count = 0;
};

/// Sum over the rows of `roi` of `row(y)` (y from 0, a Total), each row on
/// one thread, added in row order.
template<class RowFn>
Total sum_rows(const ROI& roi, int nthreads, RowFn&& row)
{
    std::vector<Total> partial(size_t(roi.height()));
    const ROI rows(0, roi.width(), 0, roi.height());
    OIIO::ImageBufAlgo::parallel_image(rows, OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y), [&](ROI r) {
        for (int y = r.ybegin; y < r.yend; ++y)
            partial[size_t(y)] = row(y);
    });
    Total total;
    for (const Total& p : partial) {
        total.sum += p.sum;
        total.count += p.count;
    }
    return total;
}

/// Marks `sums` failed with `message` about frame `frame`; returns false.
bool fail(SequenceSums& sums, int frame, const std::string& message)
{
    sums.figures.ok = false;
    sums.figures.error = format("frame {} of the sequence: {}", frame, message);
    return false;
}

/// The ROI `compare_images` settles for `result` when `roi` is undefined.
ROI settled_roi(const ImageBuf& result, ROI roi)
{
    if (roi.defined())
        return roi;
    roi = result.roi();
    roi.chbegin = 0;
    roi.chend = std::min(3, result.nchannels());
    return roi;
}

/// Sizes the running sums for the ROI settled on the first frame.
void allocate(SequenceSums& sums)
{
    const size_t values = size_t(sums.roi.npixels()) * size_t(sums.roi.nchannels());
    sums.finite.assign(size_t(sums.roi.npixels()), 1);
    sums.result_mean.assign(values, 0.0);
    sums.result_m2.assign(values, 0.0);
    sums.reference_sum.assign(values, 0.0);
}

/// Adds the relMSE of the differences between the previous frame and
/// (`x`, `r`) to the pair sum, over the pixels finite in all four images.
void add_pair(SequenceSums& sums, const std::vector<float>& x, const std::vector<float>& r)
{
    const std::vector<float>& px = sums.previous_result;
    const std::vector<float>& pr = sums.previous_reference;
    const size_t w = size_t(sums.roi.width()), nch = size_t(sums.roi.nchannels());
    const Total total = sum_rows(sums.roi, sums.nthreads, [&](int y) {
        Total row;
        for (size_t i = size_t(y) * w * nch, end = i + w * nch; i < end; i += nch) {
            bool finite = true;
            for (size_t c = i; c < i + nch; ++c)
                finite = finite && std::isfinite(x[c]) && std::isfinite(r[c]) && std::isfinite(px[c])
                         && std::isfinite(pr[c]);
            if (!finite)
                continue;
            for (size_t c = i; c < i + nch; ++c) {
                const double dx = double(x[c]) - double(px[c]);
                const double dr = double(r[c]) - double(pr[c]);
                row.sum += (dx - dr) * (dx - dr) / (dr * dr + rel_mse_epsilon);
            }
            row.count += double(nch);
        }
        return row;
    });
    sums.pair_rel_mse_sum += total.count > 0 ? total.sum / total.count : nan_value;
}

/// Adds frame (`x`, `r`) to the per-value running sums (Welford's update of
/// the mean and squared deviations; frame count `n` including this one).
void add_values(SequenceSums& sums, const std::vector<float>& x, const std::vector<float>& r, int n)
{
    const size_t nch = size_t(sums.roi.nchannels());
    OIIO::ImageBufAlgo::parallel_image(ROI(0, sums.roi.npixels(), 0, 1),
                                       OIIO::paropt(sums.nthreads), [&](ROI part) {
        for (size_t p = size_t(part.xbegin); p < size_t(part.xend); ++p)
            for (size_t c = p * nch; c < (p + 1) * nch; ++c) {
                if (!std::isfinite(x[c]) || !std::isfinite(r[c]))
                    sums.finite[p] = 0;
                const double delta = double(x[c]) - sums.result_mean[c];
                sums.result_mean[c] += delta / n;
                sums.result_m2[c] += delta * (double(x[c]) - sums.result_mean[c]);
                sums.reference_sum[c] += double(r[c]);
            }
    });
}

/// The flicker of the running sums over the pixels finite in every frame,
/// and those pixels' count.
double flicker_of(const SequenceSums& sums, int64_t& pixels)
{
    const size_t w = size_t(sums.roi.width()), nch = size_t(sums.roi.nchannels());
    const int n = sums.figures.frames;
    const Total total = sum_rows(sums.roi, sums.nthreads, [&](int y) {
        Total row;
        for (size_t p = size_t(y) * w; p < size_t(y + 1) * w; ++p) {
            if (!sums.finite[p])
                continue;
            for (size_t c = p * nch; c < (p + 1) * nch; ++c) {
                const double reference = sums.reference_sum[c] / n;
                row.sum += (sums.result_m2[c] / n) / (reference * reference + rel_mse_epsilon);
            }
            row.count += 1;
        }
        return row;
    });
    pixels = int64_t(total.count);
    return n > 1 && total.count > 0 ? total.sum / (total.count * double(nch)) : nan_value;
}

/// The ROI pixels of `image` as float; false if they cannot be read.
bool read_roi(const ImageBuf& image, const ROI& roi, std::vector<float>& pixels)
{
    pixels.resize(size_t(roi.npixels()) * size_t(roi.nchannels()));
    return image.get_pixels(roi, OIIO::TypeDesc::FLOAT, pixels.data());
}

}  // namespace

SequenceSums start_sequence(ROI roi, int nthreads)
{
    SequenceSums sums;
    sums.roi = roi;
    sums.nthreads = nthreads;
    sums.figures.ok = true;
    return sums;
}

bool add_sequence_frame(SequenceSums& sums, const ImageBuf& result, const ImageBuf& reference)
{
    const int frame = sums.figures.frames;
    if (!sums.figures.ok)
        return false;
    if (frame == 0)
        sums.roi = settled_roi(result, sums.roi);
    if (result.nchannels() < sums.roi.chend || reference.nchannels() < sums.roi.chend)
        return fail(sums, frame, format("needs channels [{},{}) like the first frame; the result has {}, the "
                                        "reference {}", sums.roi.chbegin, sums.roi.chend, result.nchannels(),
                                        reference.nchannels()));
    const ImageComparison one = compare_images(result, reference, sums.roi, sums.nthreads);
    if (!one.ok)
        return fail(sums, frame, one.error);
    std::vector<float> x, r;
    if (!read_roi(result, sums.roi, x) || !read_roi(reference, sums.roi, r))
        return fail(sums, frame, "cannot read the pixels: " + result.geterror() + reference.geterror());
    if (frame == 0)
        allocate(sums);
    else
        add_pair(sums, x, r);
    add_values(sums, x, r, frame + 1);
    sums.figures.frame_rel_mse.push_back(one.rel_mse);
    sums.figures.frames = frame + 1;
    sums.previous_result = std::move(x);
    sums.previous_reference = std::move(r);
    return true;
}

SequenceComparison sequence_comparison(const SequenceSums& sums)
{
    SequenceComparison figures = sums.figures;
    if (!figures.ok || figures.frames == 0) {
        if (figures.ok)
            figures.error = "the sequence has no frames";
        figures.ok = false;
        figures.mean_rel_mse = figures.temporal_error = figures.flicker = nan_value;
        return figures;
    }
    double sum = 0;
    for (double v : figures.frame_rel_mse)
        sum += v;
    figures.mean_rel_mse = sum / figures.frames;
    figures.temporal_error = figures.frames > 1 ? sums.pair_rel_mse_sum / (figures.frames - 1) : nan_value;
    figures.flicker = flicker_of(sums, figures.pixels);
    return figures;
}

SequenceComparison compare_sequence(const std::vector<const ImageBuf*>& results,
                                    const std::vector<const ImageBuf*>& references, ROI roi, int nthreads)
{
    SequenceSums sums = start_sequence(roi, nthreads);
    if (results.size() != references.size()) {
        SequenceComparison figures;
        figures.error = format("compare_sequence: {} result frames but {} references", results.size(),
                               references.size());
        return figures;
    }
    for (size_t t = 0; t < results.size(); ++t) {
        if (!results[t] || !references[t]) {
            fail(sums, int(t), "no image");
            break;
        }
        if (!add_sequence_frame(sums, *results[t], *references[t]))
            break;
    }
    return sequence_comparison(sums);
}

double temporal_error(const std::vector<const ImageBuf*>& results, const std::vector<const ImageBuf*>& references,
                      ROI roi, int nthreads)
{
    const SequenceComparison figures = compare_sequence(results, references, roi, nthreads);
    return figures.ok ? figures.temporal_error : nan_value;
}

double flicker(const std::vector<const ImageBuf*>& results, const std::vector<const ImageBuf*>& references,
               ROI roi, int nthreads)
{
    const SequenceComparison figures = compare_sequence(results, references, roi, nthreads);
    return figures.ok ? figures.flicker : nan_value;
}

}  // namespace mcdenoise
