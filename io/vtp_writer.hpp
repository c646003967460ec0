// VTK XML PolyData (.vtp) for ParaView: the particles as points, one vertex cell each (so
// ParaView draws them without a glyph filter), and named point-data arrays.
//
// Two encodings, both well-formed XML: ASCII (readable, values at shortest round-trip
// precision) and appended base64 (binary, about half the size and much faster to read: for
// large decks). File format version 1.0 with UInt64 block headers, native byte order.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "io/csv_writer.hpp"

namespace sphdeck::io {

enum class VtpEncoding { Ascii, Base64 };

// A point-data array of several components per point (a vector, a symmetric tensor), each
// component a separate span; written interleaved as one Float64 array with NumberOfComponents,
// which ParaView shows as one vector (3) or symmetric tensor (6: XX YY ZZ XY YZ XZ, VTK's order).
struct TupleColumn {
    std::string name;
    std::vector<std::span<const double>> components;
    std::vector<std::string> component_names;  // ComponentName0..; empty: none written
};

struct VtpPoints {
    std::span<const double> x, y, z;
    std::vector<Column> point_data;  // each as long as x: long long → Int64, double → Float64, uint32 → UInt32
    std::vector<TupleColumn> tuple_data = {};  // written after point_data
};

// Throws std::invalid_argument when array lengths differ, std::runtime_error when the stream fails.
void write_vtp(std::ostream& out, const VtpPoints& points, VtpEncoding encoding = VtpEncoding::Ascii);
// Writes `path`; throws std::runtime_error naming the file when it cannot be written.
void write_vtp_file(const std::string& path, const VtpPoints& points, VtpEncoding encoding = VtpEncoding::Ascii);

// Base64 (RFC 4648, with padding) of `bytes`, as VTK's binary blocks use it.
std::string base64(std::span<const unsigned char> bytes);

}  // namespace sphdeck::io
