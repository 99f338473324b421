// autoexposure.cpp: OIDN's autoexposure (autoexposure.h), one pass over the
// rows: each row adds its pixels' luminances to the sums of its band of
// bins, and a band's bins are averaged once its last row is in.
#include "network/autoexposure.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace mcdenoise {

namespace {

/// A colour value sanitised as OIDN's autoexposure does: NaN to 0, then
/// clamped to [0, FLT_MAX].
inline double sanitized(float v)
{
    return std::isnan(v) ? 0.0 : double(std::min(std::max(v, 0.f), FLT_MAX));
}

/// The log2 sum and count of the kept bins.
struct LogSum {
    double sum = 0;
    int count  = 0;
};

/// Adds the luminances of row `y` of `image` to `sums`, one per bin
/// column, whose first columns are `begins` (one more than the bins).
void add_row(const RgbIn& image, int y, const std::vector<int>& begins, std::vector<double>& sums)
{
    const float* p = image.pixel(0, y);
    for (size_t j = 0; j + 1 < begins.size(); ++j) {
        double s = 0;
        for (int x = begins[j]; x < begins[j + 1]; ++x, p += image.pixel_stride)
            s += autoexposure_luminance(sanitized(p[0]), sanitized(p[1]), sanitized(p[2]));
        sums[j] += s;
    }
}

/// Adds the log2 of each bin average of a band `rows` high whose sums are
/// `sums` to `logs`, leaving out averages of `autoexposure_eps` or less.
void add_band(const std::vector<double>& sums, const std::vector<int>& begins, int rows,
              LogSum& logs)
{
    for (size_t j = 0; j < sums.size(); ++j) {
        const double mean = sums[j] / (double(rows) * double(begins[j + 1] - begins[j]));
        if (mean > double(autoexposure_eps)) {
            logs.sum += std::log2(mean);
            ++logs.count;
        }
    }
}

}  // namespace

int autoexposure_bins(int size)
{
    return int((static_cast<long long>(size) + autoexposure_bin_size - 1) / autoexposure_bin_size);
}

int autoexposure_bin_begin(int i, int size, int bins)
{
    return int(static_cast<long long>(i) * size / bins);
}

double autoexposure_luminance(double r, double g, double b)
{
    return 0.212671 * r + 0.715160 * g + 0.072169 * b;
}

bool autoexposure(const RgbIn& image, float& scale)
{
    if (!image.valid())
        return false;
    const int bins_x = autoexposure_bins(image.width);
    const int bins_y = autoexposure_bins(image.height);
    std::vector<int> begins(size_t(bins_x) + 1);
    for (int j = 0; j <= bins_x; ++j)
        begins[size_t(j)] = autoexposure_bin_begin(j, image.width, bins_x);
    std::vector<double> sums(begins.size() - 1);
    LogSum logs;
    for (int i = 0; i < bins_y; ++i) {
        const int y0 = autoexposure_bin_begin(i, image.height, bins_y);
        const int y1 = autoexposure_bin_begin(i + 1, image.height, bins_y);
        std::fill(sums.begin(), sums.end(), 0.0);
        for (int y = y0; y < y1; ++y)
            add_row(image, y, begins, sums);
        add_band(sums, begins, y1 - y0, logs);
    }
    scale = logs.count > 0
                ? float(double(autoexposure_key) / std::exp2(logs.sum / double(logs.count)))
                : 1.f;
    return true;
}

}  // namespace mcdenoise
