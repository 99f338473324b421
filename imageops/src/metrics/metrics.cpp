// metrics.cpp: relMSE, MSE, PSNR and SSIM over a ROI. The pixels of both
// images are read once as float; per-row partial sums are computed in
// parallel and added in row order, so results do not depend on the threads.
#include <mcdenoise/metrics.h>

#include <OpenImageIO/imagebufalgo_util.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mcdenoise {

namespace {

using OIIO::ImageSpec;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
/// Rec.709 / sRGB luminance weights.
constexpr double luma_r = 0.2126, luma_g = 0.7152, luma_b = 0.0722;
constexpr int ssim_radius = ssim_window_size / 2;

std::string roi_text(const ROI& r)
{
    return OIIO::Strutil::fmt::format("[{},{})x[{},{})", r.xbegin, r.xend, r.ybegin, r.yend);
}

bool covers(const ROI& data, const ROI& roi)
{
    return roi.xbegin >= data.xbegin && roi.xend <= data.xend && roi.ybegin >= data.ybegin
           && roi.yend <= data.yend;
}

/// Settle the ROI and check both images against it; false with `error` set.
bool settle_roi(const ImageBuf& result, const ImageBuf& reference, ROI& roi,
                std::string& error)
{
    const ImageBuf* images[] = { &result, &reference };
    const char* names[] = { "result", "reference" };
    for (int i = 0; i < 2; ++i) {
        const ImageSpec& spec = images[i]->spec();  // reads the header of a file-backed image
        if (!images[i]->initialized() || spec.nchannels < 1 || spec.width < 1 || spec.height < 1) {
            error = OIIO::Strutil::fmt::format("compare_images: the {} image is empty{}{}",
                                               names[i], images[i]->has_error() ? ": " : "",
                                               images[i]->has_error() ? images[i]->geterror() : "");
            return false;
        }
        if (spec.depth > 1) {
            error = OIIO::Strutil::fmt::format("compare_images: the {} image is a volume", names[i]);
            return false;
        }
    }
    const int nch = std::min(result.nchannels(), reference.nchannels());
    if (!roi.defined()) {
        roi = result.roi();
        roi.chbegin = 0;
        roi.chend = std::min(3, result.nchannels());
    } else {
        roi.chend = std::min(roi.chend, nch);
    }
    roi.zbegin = 0;
    roi.zend = 1;
    if (roi.chbegin < 0 || roi.chbegin >= roi.chend || roi.chend > nch) {
        error = OIIO::Strutil::fmt::format(
            "compare_images: the ROI needs channels [{},{}) but the result has {} and the "
            "reference {}",
            roi.chbegin, std::max(roi.chend, roi.chbegin + 1), result.nchannels(),
            reference.nchannels());
        return false;
    }
    if (roi.width() < 1 || roi.height() < 1) {
        error = "compare_images: the ROI is empty";
        return false;
    }
    for (int i = 0; i < 2; ++i) {
        if (!covers(images[i]->roi(), roi)) {
            error = OIIO::Strutil::fmt::format(
                "compare_images: the {} image's data window {} does not cover the ROI {}",
                names[i], roi_text(images[i]->roi()), roi_text(roi));
            return false;
        }
    }
    return true;
}

/// Run `row(y)` for y in [0, height) on up to `nthreads` threads.
template<class RowFn>
void for_rows(const ROI& roi, int nthreads, RowFn&& row)
{
    const ROI rows(0, roi.width(), 0, roi.height());
    OIIO::ImageBufAlgo::parallel_image(rows, OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y),
                                       [&](ROI r) {
                                           for (int y = r.ybegin; y < r.yend; ++y)
                                               row(y);
                                       });
}

/// The gaussian taps of the SSIM window, offsets -radius..radius.
std::vector<double> ssim_taps()
{
    std::vector<double> taps(ssim_window_size);
    for (int k = -ssim_radius; k <= ssim_radius; ++k)
        taps[size_t(k + ssim_radius)] = std::exp(-double(k * k) / (2 * ssim_sigma * ssim_sigma));
    return taps;
}

/// Mean SSIM of luminance planes `lx`, `ly` (w x h) where `mask` is 1 for
/// finite pixels and 0 for left-out ones.
double mean_ssim(const std::vector<double>& lx, const std::vector<double>& ly,
                 const std::vector<double>& mask, int w, int h, int nthreads)
{
    constexpr int nplanes = 6;  // weight, x, y, x^2, y^2, xy (all masked)
    const size_t npix = size_t(w) * size_t(h);
    std::vector<double> moments(npix * nplanes), blurred(npix * nplanes), horiz(npix * nplanes);
    for (size_t i = 0; i < npix; ++i) {
        const double m = mask[i], x = lx[i], y = ly[i];
        double* p = &moments[i * nplanes];
        p[0] = m;
        p[1] = m * x;
        p[2] = m * y;
        p[3] = m * x * x;
        p[4] = m * y * y;
        p[5] = m * x * y;
    }
    const std::vector<double> taps = ssim_taps();
    const ROI whole(0, w, 0, h);
    // horizontal pass, then vertical pass, clipped to the image
    for_rows(whole, nthreads, [&](int y) {
        for (int x = 0; x < w; ++x) {
            double acc[nplanes] = {};
            for (int k = std::max(-ssim_radius, -x); k <= std::min(ssim_radius, w - 1 - x); ++k) {
                const double t = taps[size_t(k + ssim_radius)];
                const double* p = &moments[(size_t(y) * w + size_t(x + k)) * nplanes];
                for (int c = 0; c < nplanes; ++c)
                    acc[c] += t * p[c];
            }
            for (int c = 0; c < nplanes; ++c)
                horiz[(size_t(y) * w + size_t(x)) * nplanes + size_t(c)] = acc[c];
        }
    });
    for_rows(whole, nthreads, [&](int y) {
        for (int x = 0; x < w; ++x) {
            double acc[nplanes] = {};
            for (int k = std::max(-ssim_radius, -y); k <= std::min(ssim_radius, h - 1 - y); ++k) {
                const double t = taps[size_t(k + ssim_radius)];
                const double* p = &horiz[(size_t(y + k) * w + size_t(x)) * nplanes];
                for (int c = 0; c < nplanes; ++c)
                    acc[c] += t * p[c];
            }
            for (int c = 0; c < nplanes; ++c)
                blurred[(size_t(y) * w + size_t(x)) * nplanes + size_t(c)] = acc[c];
        }
    });
    const double c1 = (ssim_k1 * 1.0) * (ssim_k1 * 1.0);
    const double c2 = (ssim_k2 * 1.0) * (ssim_k2 * 1.0);
    std::vector<double> row_sum(static_cast<size_t>(h), 0.0);
    for_rows(whole, nthreads, [&](int y) {
        double sum = 0;
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + size_t(x);
            if (mask[i] == 0)
                continue;
            const double* b = &blurred[i * nplanes];
            const double inv = 1.0 / b[0];  // > 0: the center itself contributes
            const double mx = b[1] * inv, my = b[2] * inv;
            const double vx = std::max(0.0, b[3] * inv - mx * mx);
            const double vy = std::max(0.0, b[4] * inv - my * my);
            const double cxy = b[5] * inv - mx * my;
            sum += ((2 * mx * my + c1) * (2 * cxy + c2))
                   / ((mx * mx + my * my + c1) * (vx + vy + c2));
        }
        row_sum[size_t(y)] = sum;
    });
    double total = 0, count = 0;
    for (int y = 0; y < h; ++y)
        total += row_sum[size_t(y)];
    for (double m : mask)
        count += m;
    return total / count;
}

}  // namespace

ImageComparison compare_images(const ImageBuf& result, const ImageBuf& reference, ROI roi,
                               int nthreads)
{
    ImageComparison cmp;
    if (!settle_roi(result, reference, roi, cmp.error))
        return cmp;
    const int w = roi.width(), h = roi.height(), nch = roi.nchannels();
    const size_t npix = size_t(w) * size_t(h);
    std::vector<float> xs(npix * size_t(nch)), rs(npix * size_t(nch));
    if (!result.get_pixels(roi, OIIO::TypeDesc::FLOAT, xs.data())) {
        cmp.error = "compare_images: cannot read the result: " + result.geterror();
        return cmp;
    }
    if (!reference.get_pixels(roi, OIIO::TypeDesc::FLOAT, rs.data())) {
        cmp.error = "compare_images: cannot read the reference: " + reference.geterror();
        return cmp;
    }

    // per pixel: finite mask and clamped luminance; per row: error sums
    std::vector<double> mask(npix), lx(npix), ly(npix);
    std::vector<double> row_sq(static_cast<size_t>(h)), row_rel(static_cast<size_t>(h));
    std::vector<double> row_peak_sq(static_cast<size_t>(h));  // on values clamped to [0, psnr_peak], for PSNR
    for_rows(roi, nthreads, [&](int y) {
        double sq = 0, rel = 0, peak_sq = 0;
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + size_t(x);
            const float* px = &xs[i * size_t(nch)];
            const float* pr = &rs[i * size_t(nch)];
            bool finite = true;
            for (int c = 0; c < nch; ++c)
                finite = finite && std::isfinite(px[c]) && std::isfinite(pr[c]);
            mask[i] = finite ? 1.0 : 0.0;
            lx[i] = ly[i] = 0;
            if (!finite)
                continue;
            for (int c = 0; c < nch; ++c) {
                const double d = double(px[c]) - double(pr[c]);
                sq += d * d;
                rel += d * d / (double(pr[c]) * double(pr[c]) + rel_mse_epsilon);
                const double dc = std::clamp(double(px[c]), 0.0, psnr_peak) - std::clamp(double(pr[c]), 0.0, psnr_peak);
                peak_sq += dc * dc;
            }
            double yx = 0, yr = 0;
            if (nch >= 3) {
                yx = luma_r * px[0] + luma_g * px[1] + luma_b * px[2];
                yr = luma_r * pr[0] + luma_g * pr[1] + luma_b * pr[2];
            } else {
                for (int c = 0; c < nch; ++c) {
                    yx += px[c];
                    yr += pr[c];
                }
                yx /= nch;
                yr /= nch;
            }
            lx[i] = std::clamp(yx, 0.0, 1.0);
            ly[i] = std::clamp(yr, 0.0, 1.0);
        }
        row_sq[size_t(y)] = sq;
        row_rel[size_t(y)] = rel;
        row_peak_sq[size_t(y)] = peak_sq;
    });
    double sq = 0, rel = 0, peak_sq = 0;
    int64_t finite_pixels = 0;
    for (int y = 0; y < h; ++y) {
        sq += row_sq[size_t(y)];
        rel += row_rel[size_t(y)];
        peak_sq += row_peak_sq[size_t(y)];
    }
    for (double m : mask)
        finite_pixels += m != 0 ? 1 : 0;

    cmp.ok = true;
    cmp.pixels = finite_pixels;
    cmp.nonfinite = int64_t(npix) - finite_pixels;
    if (finite_pixels == 0) {
        cmp.rel_mse = cmp.mse = cmp.psnr = cmp.ssim = nan_value;
        return cmp;
    }
    const double values = double(finite_pixels) * nch;
    cmp.mse = sq / values;
    cmp.rel_mse = rel / values;
    const double clamped_mse = peak_sq / values;
    cmp.psnr = clamped_mse > 0 ? 10 * std::log10(psnr_peak * psnr_peak / clamped_mse)
                               : std::numeric_limits<double>::infinity();
    cmp.ssim = mean_ssim(lx, ly, mask, w, h, nthreads);
    return cmp;
}

double rel_mse(const ImageBuf& result, const ImageBuf& reference, ROI roi, int nthreads)
{
    const ImageComparison c = compare_images(result, reference, roi, nthreads);
    return c.ok ? c.rel_mse : nan_value;
}

double mse(const ImageBuf& result, const ImageBuf& reference, ROI roi, int nthreads)
{
    const ImageComparison c = compare_images(result, reference, roi, nthreads);
    return c.ok ? c.mse : nan_value;
}

double psnr(const ImageBuf& result, const ImageBuf& reference, ROI roi, int nthreads)
{
    const ImageComparison c = compare_images(result, reference, roi, nthreads);
    return c.ok ? c.psnr : nan_value;
}

double ssim(const ImageBuf& result, const ImageBuf& reference, ROI roi, int nthreads)
{
    const ImageComparison c = compare_images(result, reference, roi, nthreads);
    return c.ok ? c.ssim : nan_value;
}

}  // namespace mcdenoise
