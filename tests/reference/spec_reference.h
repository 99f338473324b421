// spec_reference.h: an independent, deliberately plain implementation of
// docs/filters.md's window filters for the tests: double precision, every window
// visited neighbour by neighbour, no shortcuts shared with the library.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <functional>
#include <vector>

namespace spec {

/// An image's data window as doubles, channels interleaved.
struct Image {
    int x0 = 0, y0 = 0, width = 0, height = 0, nchannels = 0;
    std::vector<double> values;

    double at(int x, int y, int c) const
    {
        return values[(size_t(y - y0) * width + size_t(x - x0)) * nchannels + size_t(c)];
    }
    bool contains(int x, int y) const
    {
        return x >= x0 && x < x0 + width && y >= y0 && y < y0 + height;
    }
};

/// Every pixel of `img`'s data window, converted to double.
Image from_imagebuf(const OIIO::ImageBuf& img);

/// `from_imagebuf` for ids: the integer formats uint8, uint16, uint32 and
/// int32 give the whole numbers they store (OIIO's conversion would scale
/// them to [0, 1]); ids are whole numbers (docs/filters.md).
Image ids_from_imagebuf(const OIIO::ImageBuf& img);

/// How a window's viable values become one value.
enum class Reduce { weighted_mean, median };

/// Whether neighbour q of center p takes part (the center always does).
using Viable = std::function<bool(int px, int py, int qx, int qy)>;
/// The guide weight of neighbour q for center p (multiplies the spatial weight).
using GuideWeight = std::function<double(int px, int py, int qx, int qy)>;

/// Spatial weights: 1 everywhere (box) or binomial (Pascal's triangle).
enum class Spatial { box, binomial };

/// The filter of docs/filters.md over `roi` (x, y and channels): for every pixel and
/// channel, the viable finite values of the window of side `size` clipped to
/// the beauty's data window, reduced by `reduce`; 0 where none is there.
/// Returns roi.width() * roi.height() * roi.nchannels() values.
std::vector<double> filter(const Image& beauty, const OIIO::ROI& roi, int size,
                           Spatial spatial, Reduce reduce, const Viable& viable,
                           const GuideWeight& guide_weight);

/// Every neighbour is viable / weighs 1.
bool all_viable(int, int, int, int);
double unit_weight(int, int, int, int);

/// C(n, k) as a double (exact for the sizes the tests use).
double binomial(int n, int k);

}  // namespace spec
