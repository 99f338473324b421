// tza.h: the reader of Open Image Denoise's weight files (.tza, the format of
// OIDN 2.x's training/tza.py, version 2.0): a named set of float32 or
// float16 tensors, read into float32 with every bound of the file checked;
// implemented in tza.cpp. The byte layout is in docs/network.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mcdenoise {

/// The first two bytes of a .tza file, little-endian.
constexpr uint16_t tza_magic = 0x41D7;
/// The format version read: 2.0 (OIDN 2.x).
constexpr uint8_t tza_version_major = 2;
constexpr uint8_t tza_version_minor = 0;
/// Bytes of the header: magic (2), version (2), table offset (8).
constexpr size_t tza_header_size = 12;
/// The most dimensions a tensor may have.
constexpr int tza_max_dims = 4;

/// One tensor of a .tza file, its values converted to float32.
struct Tensor {
    /// The tensor's name, e.g. "enc_conv0.weight".
    std::string name;
    /// Its dimensions, outermost first, each > 0; as many as `layout` has
    /// characters.
    std::vector<int> dims;
    /// One character per dimension: "oihw" (a convolution's weights: out
    /// channels, in channels, height, width) or "x" (a bias).
    std::string layout;
    /// The values, row-major in the order of `dims`; as many as the product
    /// of the dimensions.
    std::vector<float> values;
};

/// The tensors of a file, by name.
using TensorMap = std::map<std::string, Tensor>;

/// The float32 of the IEEE 754 binary16 value `bits`: exact for every value
/// (normals, subnormals, signed zeros, infinities; a NaN stays a NaN with
/// its sign and payload).
float half_to_float(uint16_t bits);

/// Parses the .tza bytes `data` (`size` bytes) into `tensors`. `source`
/// names the bytes in the error (a file name). Returns true on success;
/// false with `tensors` empty and `error` saying what is wrong, naming
/// `source` and the tensor, on anything out of bounds or unknown: the magic
/// or the version, the table or a tensor's data outside the bytes, an empty
/// or truncated name, a duplicate name, 0 or more than `tza_max_dims`
/// dimensions, a zero dimension or a product that overflows, a layout other
/// than "x" or "oihw" (or not matching the dimensions), a data type other
/// than 'f' (float32) or 'h' (float16), tensors whose data add up to more
/// than the file (overlapping).
bool parse_tza(const void* data, size_t size, const std::string& source, TensorMap& tensors,
               std::string& error);

/// Reads the .tza file at `path` into `tensors`, as `parse_tza` does; the
/// error names `path` (also when it cannot be opened or read).
bool read_tza(const std::string& path, TensorMap& tensors, std::string& error);

}  // namespace mcdenoise
