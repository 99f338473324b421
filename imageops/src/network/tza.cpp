// tza.cpp: the .tza reader (tza.h): a bounds-checked little-endian cursor
// over the bytes, the table of tensors, and the float16 to float32
// conversion.
#include "network/tza.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

namespace mcdenoise {

namespace {

/// Bits of a float16's mantissa, and the float32's.
constexpr int half_mantissa_bits  = 10;
constexpr int float_mantissa_bits = 23;
/// The exponent biases of float16 and float32.
constexpr int half_exponent_bias  = 15;
constexpr int float_exponent_bias = 127;
/// A float16's exponent field of infinities and NaNs.
constexpr uint32_t half_exponent_max = 0x1F;
/// A float32's exponent field of infinities and NaNs.
constexpr uint32_t float_exponent_max = 0xFF;
/// The data types of a tensor and their sizes in bytes.
constexpr char dtype_float32   = 'f';
constexpr char dtype_float16   = 'h';
constexpr size_t float32_bytes = 4;
constexpr size_t float16_bytes = 2;
/// The layouts this reader knows: a convolution's weights, a bias.
const char* const known_layouts[] = { "oihw", "x" };

/// Reads little-endian values from bytes, never past their end.
class Cursor {
public:
    Cursor(const unsigned char* data, size_t size)
        : data_(data)
        , size_(size)
    {
    }

    /// Moves to `offset`; false if it is past the end.
    bool seek(uint64_t offset)
    {
        if (offset > size_)
            return false;
        pos_ = size_t(offset);
        return true;
    }

    /// Reads an unsigned little-endian integer of sizeof(T) bytes.
    template<class T>
    bool read(T& value)
    {
        if (size_ - pos_ < sizeof(T))
            return false;
        uint64_t v = 0;
        for (size_t i = 0; i < sizeof(T); ++i)
            v |= uint64_t(data_[pos_ + i]) << (8 * i);
        value = T(v);
        pos_ += sizeof(T);
        return true;
    }

    /// Reads `n` bytes as a string.
    bool read_string(size_t n, std::string& s)
    {
        if (size_ - pos_ < n)
            return false;
        s.assign(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        return true;
    }

private:
    const unsigned char* data_;
    size_t size_;
    size_t pos_ = 0;
};

bool known_layout(const std::string& layout)
{
    for (const char* known : known_layouts)
        if (layout == known)
            return true;
    return false;
}

/// What a layout is expected to look like, for the error.
std::string layouts_text()
{
    std::string s;
    for (const char* known : known_layouts)
        s += (s.empty() ? "\"" : " or \"") + std::string(known) + "\"";
    return s;
}

/// The values of a tensor of `count` elements of `dtype` at `bytes`.
void convert_values(const unsigned char* bytes, size_t count, char dtype, std::vector<float>& out)
{
    out.resize(count);
    if (dtype == dtype_float32) {
        for (size_t i = 0; i < count; ++i) {
            const unsigned char* b = bytes + i * float32_bytes;
            const uint32_t bits =
                uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
            std::memcpy(&out[i], &bits, sizeof(bits));
        }
    } else {
        for (size_t i = 0; i < count; ++i) {
            const unsigned char* b = bytes + i * float16_bytes;
            out[i]                 = half_to_float(uint16_t(b[0] | b[1] << 8));
        }
    }
}

/// Parses one table entry into `t`; on failure `error` says what is wrong
/// (without the source, which the caller adds). `unclaimed` is the bytes of
/// the file past the header that earlier tensors' data have not taken: the
/// data of all tensors cannot add up to more than the file, so overlapping
/// tensors cannot make the values outgrow it.
bool parse_entry(Cursor& in, const unsigned char* data, size_t size, uint32_t index, Tensor& t,
                 uint64_t& unclaimed, std::string& error)
{
    const std::string entry = "tensor #" + std::to_string(index);
    uint16_t name_length    = 0;
    if (!in.read(name_length) || !in.read_string(name_length, t.name)) {
        error = entry + ": the table runs past the end of the file (truncated?)";
        return false;
    }
    if (t.name.empty()) {
        error = entry + ": empty name";
        return false;
    }
    const std::string what      = "tensor '" + t.name + "'";
    const std::string truncated = what + ": the table runs past the end of the file (truncated?)";
    uint8_t ndims               = 0;
    if (!in.read(ndims)) {
        error = truncated;
        return false;
    }
    if (ndims < 1 || ndims > tza_max_dims) {
        error = what + ": " + std::to_string(ndims) + " dimensions (a tensor has 1 to "
                + std::to_string(tza_max_dims) + ")";
        return false;
    }
    uint64_t count = 1;
    t.dims.resize(ndims);
    for (int d = 0; d < ndims; ++d) {
        uint32_t dim = 0;
        if (!in.read(dim)) {
            error = truncated;
            return false;
        }
        if (dim == 0 || dim > uint32_t(std::numeric_limits<int>::max())) {
            error = what + ": dimension " + std::to_string(d) + " is " + std::to_string(dim)
                    + " (must be 1 to " + std::to_string(std::numeric_limits<int>::max()) + ")";
            return false;
        }
        if (count > std::numeric_limits<uint64_t>::max() / dim) {
            error = what + ": the product of its dimensions overflows";
            return false;
        }
        count *= dim;
        t.dims[d] = int(dim);
    }
    uint8_t dtype   = 0;
    uint64_t offset = 0;
    if (!in.read_string(ndims, t.layout) || !in.read(dtype) || !in.read(offset)) {
        error = truncated;
        return false;
    }
    if (!known_layout(t.layout)) {
        error = what + ": layout \"" + t.layout + "\" (known: " + layouts_text() + ")";
        return false;
    }
    if (dtype != uint8_t(dtype_float32) && dtype != uint8_t(dtype_float16)) {
        error =
            what + ": data type " + std::to_string(dtype) + " (known: 'f' float32, 'h' float16)";
        return false;
    }
    const size_t element = dtype == uint8_t(dtype_float32) ? float32_bytes : float16_bytes;
    if (offset < tza_header_size) {
        error = what + ": data at offset " + std::to_string(offset) + ", inside the header";
        return false;
    }
    // count * element cannot overflow once count <= size / element.
    if (offset > size || count > (size - offset) / element) {
        error = what + ": data runs past the end of the file (truncated?)";
        return false;
    }
    if (count * element > unclaimed) {
        error = what + ": the tensors' data add up to more than the file (overlapping data?)";
        return false;
    }
    unclaimed -= count * element;
    convert_values(data + offset, size_t(count), char(dtype), t.values);
    return true;
}

}  // namespace

float half_to_float(uint16_t bits)
{
    const uint32_t sign       = uint32_t(bits >> 15) << 31;
    const uint32_t exponent   = (bits >> half_mantissa_bits) & half_exponent_max;
    uint32_t mantissa         = bits & ((1u << half_mantissa_bits) - 1);
    constexpr int shift       = float_mantissa_bits - half_mantissa_bits;
    constexpr uint32_t rebias = float_exponent_bias - half_exponent_bias;
    uint32_t out              = sign;
    if (exponent == half_exponent_max) {
        // infinity, or a NaN keeping its payload
        out |= float_exponent_max << float_mantissa_bits | mantissa << shift;
    } else if (exponent != 0) {
        out |= (exponent + rebias) << float_mantissa_bits | mantissa << shift;
    } else if (mantissa != 0) {
        // subnormal: mantissa * 2^-24, normalised so its leading 1 is implicit
        uint32_t e = rebias + 1;
        while (!(mantissa & (1u << half_mantissa_bits))) {
            mantissa <<= 1;
            --e;
        }
        mantissa &= (1u << half_mantissa_bits) - 1;
        out |= e << float_mantissa_bits | mantissa << shift;
    }
    float f;
    std::memcpy(&f, &out, sizeof(f));
    return f;
}

bool parse_tza(const void* data, size_t size, const std::string& source, TensorMap& tensors,
               std::string& error)
{
    tensors.clear();
    const auto* bytes = static_cast<const unsigned char*>(data);
    Cursor in(bytes, size);
    uint16_t magic = 0;
    uint8_t major = 0, minor = 0;
    uint64_t table = 0;
    if (!in.read(magic) || !in.read(major) || !in.read(minor) || !in.read(table)) {
        error = source + ": " + std::to_string(size) + " bytes, shorter than a .tza header ("
                + std::to_string(tza_header_size) + " bytes; truncated?)";
        return false;
    }
    if (magic != tza_magic) {
        std::ostringstream s;
        s << source << ": not a .tza file (magic 0x" << std::hex << std::uppercase << magic
          << ", expected 0x" << tza_magic << ")";
        error = s.str();
        return false;
    }
    if (major != tza_version_major || minor != tza_version_minor) {
        error = source + ": .tza version " + std::to_string(major) + "." + std::to_string(minor)
                + " (this reader reads " + std::to_string(tza_version_major) + "."
                + std::to_string(tza_version_minor) + ", OIDN 2.x's weights)";
        return false;
    }
    uint32_t count = 0;
    if (table < tza_header_size || !in.seek(table) || !in.read(count)) {
        error = source + ": the table offset " + std::to_string(table)
                + " is outside the file (truncated?)";
        return false;
    }
    TensorMap read;
    uint64_t unclaimed = size - tza_header_size;
    for (uint32_t i = 0; i < count; ++i) {
        Tensor t;
        std::string what;
        if (!parse_entry(in, bytes, size, i, t, unclaimed, what)) {
            error = source + ": " + what;
            return false;
        }
        if (read.count(t.name)) {
            error = source + ": tensor '" + t.name + "' appears twice";
            return false;
        }
        std::string name = t.name;
        read.emplace(std::move(name), std::move(t));
    }
    tensors.swap(read);
    return true;
}

bool read_tza(const std::string& path, TensorMap& tensors, std::string& error)
{
    tensors.clear();
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = path + ": cannot be opened (" + std::strerror(errno) + ")";
        return false;
    }
    const std::string bytes((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
    if (file.bad()) {
        error = path + ": cannot be read (" + std::strerror(errno) + ")";
        return false;
    }
    return parse_tza(bytes.data(), bytes.size(), path, tensors, error);
}

}  // namespace mcdenoise
