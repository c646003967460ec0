#include "io/vtp_writer.hpp"

#include "io/xml_escape.hpp"

#include <bit>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace sphdeck::io {
namespace {

constexpr char base64_alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Takes values one by one and writes them in the chosen encoding into a buffer that is flushed
// to the stream now and then.
class Sink {
public:
    Sink(std::ostream& out, VtpEncoding encoding) : out_(out), encoding_(encoding) {}
    void put(double v) { encoding_ == VtpEncoding::Ascii ? text(v) : put_bytes(&v, sizeof v); }
    void put(long long v) {
        const std::int64_t w = v;
        encoding_ == VtpEncoding::Ascii ? text(w) : put_bytes(&w, sizeof w);
    }
    void put(std::uint32_t v) { encoding_ == VtpEncoding::Ascii ? text(v) : put_bytes(&v, sizeof v); }

    // Ends a block: a line break in ASCII, the base64 padding otherwise.
    void end_block() {
        if (encoding_ == VtpEncoding::Ascii) {
            if (in_line_ > 0) buffer_.push_back('\n');
            in_line_ = 0;
        } else if (pending_ > 0) {
            unsigned char g[3] = {group_[0], pending_ > 1 ? group_[1] : static_cast<unsigned char>(0), 0};
            const char out[4] = {base64_alphabet[g[0] >> 2], base64_alphabet[((g[0] & 3) << 4) | (g[1] >> 4)],
                                 pending_ > 1 ? base64_alphabet[(g[1] & 15) << 2] : '=', '='};
            buffer_.append(out, out + 4);
            pending_ = 0;
        }
        maybe_flush();
    }
    void put_bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) {
            group_[pending_++] = p[i];
            if (pending_ == 3) {
                const char out[4] = {base64_alphabet[group_[0] >> 2],
                                     base64_alphabet[((group_[0] & 3) << 4) | (group_[1] >> 4)],
                                     base64_alphabet[((group_[1] & 15) << 2) | (group_[2] >> 6)],
                                     base64_alphabet[group_[2] & 63]};
                buffer_.append(out, out + 4);
                pending_ = 0;
            }
        }
        maybe_flush();
    }
    void raw(std::string_view s) { buffer_.append(s.data(), s.data() + s.size()); }
    void flush() {
        out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }

private:
    template <typename T>
    void text(T v) {
        if (in_line_ > 0) buffer_.push_back(' ');
        fmt::format_to(std::back_inserter(buffer_), "{}", v);
        if (++in_line_ == 6) {
            buffer_.push_back('\n');
            in_line_ = 0;
            maybe_flush();
        }
    }
    void maybe_flush() {
        if (buffer_.size() > (1u << 20)) flush();
    }

    std::ostream& out_;
    VtpEncoding encoding_;
    fmt::memory_buffer buffer_;
    int in_line_ = 0;
    unsigned char group_[3] = {0, 0, 0};
    int pending_ = 0;
};

// One DataArray: its XML attributes and how to produce its values.
struct Block {
    std::string name;
    std::string_view type;
    int components = 1;
    std::size_t values = 0;  // tuples * components
    std::size_t value_bytes = 8;
    std::function<void(Sink&)> emit;
    std::vector<std::string> component_names = {};

    std::size_t encoded_size() const {  // header and data, each base64-encoded on its own
        return 4 * ((sizeof(std::uint64_t) + 2) / 3) + 4 * ((values * value_bytes + 2) / 3);
    }
};

Block column_block(const Column& c) {
    Block b;
    b.name = c.name;
    b.values = c.size();
    std::visit(
        [&](const auto& span) {
            using T = typename std::decay_t<decltype(span)>::value_type;
            b.value_bytes = sizeof(T);
            b.type = std::is_same_v<T, double> ? "Float64" : std::is_same_v<T, long long> ? "Int64" : "UInt32";
            b.emit = [span](Sink& s) {
                for (T v : span) s.put(v);
            };
        },
        c.values);
    return b;
}

Block tuple_block(const TupleColumn& c, std::size_t n) {
    const int k = static_cast<int>(c.components.size());
    return {c.name,
            "Float64",
            k,
            n * c.components.size(),
            8,
            [&c, n](Sink& s) {
                for (std::size_t i = 0; i < n; ++i)
                    for (std::span<const double> component : c.components) s.put(component[i]);
            },
            c.component_names};
}

std::vector<Block> blocks_of(const VtpPoints& p) {
    const std::size_t n = p.x.size();
    std::vector<Block> blocks;
    for (const Column& c : p.point_data) blocks.push_back(column_block(c));
    for (const TupleColumn& c : p.tuple_data) blocks.push_back(tuple_block(c, n));
    blocks.push_back({"Points", "Float64", 3, 3 * n, 8, [&p, n](Sink& s) {
                          for (std::size_t i = 0; i < n; ++i) {
                              s.put(p.x[i]);
                              s.put(p.y[i]);
                              s.put(p.z[i]);
                          }
                      }});
    blocks.push_back({"connectivity", "Int64", 1, n, 8, [n](Sink& s) {
                          for (std::size_t i = 0; i < n; ++i) s.put(static_cast<long long>(i));
                      }});
    blocks.push_back({"offsets", "Int64", 1, n, 8, [n](Sink& s) {
                          for (std::size_t i = 0; i < n; ++i) s.put(static_cast<long long>(i + 1));
                      }});
    return blocks;
}

}  // namespace

std::string base64(std::span<const unsigned char> bytes) {
    std::ostringstream out;
    Sink sink(out, VtpEncoding::Base64);
    sink.put_bytes(bytes.data(), bytes.size());
    sink.end_block();
    sink.flush();
    return out.str();
}

void write_vtp(std::ostream& out, const VtpPoints& points, VtpEncoding encoding) {
    const std::size_t n = points.x.size();
    if (points.y.size() != n || points.z.size() != n) throw std::invalid_argument("vtp coordinates differ in length");
    for (const Column& c : points.point_data)
        if (c.size() != n)
            throw std::invalid_argument(fmt::format("vtp array '{}' has {} values, expected {}", c.name, c.size(), n));
    for (const TupleColumn& c : points.tuple_data) {
        if (c.components.empty()) throw std::invalid_argument(fmt::format("vtp array '{}' has no components", c.name));
        for (std::span<const double> component : c.components)
            if (component.size() != n)
                throw std::invalid_argument(
                    fmt::format("vtp array '{}' has {} values, expected {}", c.name, component.size(), n));
    }

    const std::vector<Block> blocks = blocks_of(points);
    const bool ascii = encoding == VtpEncoding::Ascii;
    std::vector<std::size_t> offsets(blocks.size(), 0);
    for (std::size_t i = 1; i < blocks.size(); ++i) offsets[i] = offsets[i - 1] + blocks[i - 1].encoded_size();

    Sink sink(out, encoding);
    auto header = [&](std::size_t i, std::string_view indent) {
        const Block& b = blocks[i];
        sink.raw(fmt::format("{}<DataArray type=\"{}\" Name=\"{}\"", indent, b.type, xml_escape(b.name)));
        if (b.components != 1) sink.raw(fmt::format(" NumberOfComponents=\"{}\"", b.components));
        for (std::size_t k = 0; k < b.component_names.size(); ++k)
            sink.raw(fmt::format(" ComponentName{}=\"{}\"", k, xml_escape(b.component_names[k])));
        if (ascii) {
            sink.raw(" format=\"ascii\">\n");
            b.emit(sink);
            sink.end_block();
            sink.raw(fmt::format("{}</DataArray>\n", indent));
        } else {
            sink.raw(fmt::format(" format=\"appended\" offset=\"{}\"/>\n", offsets[i]));
        }
    };
    sink.raw(
        fmt::format("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"{}\" "
                    "header_type=\"UInt64\">\n  <PolyData>\n",
                    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"));
    sink.raw(
        fmt::format("    <Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" NumberOfLines=\"0\" "
                    "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                    n));
    const std::size_t arrays = points.point_data.size() + points.tuple_data.size();
    sink.raw("      <PointData>\n");
    for (std::size_t i = 0; i < arrays; ++i) header(i, "        ");
    sink.raw("      </PointData>\n      <Points>\n");
    header(arrays, "        ");
    sink.raw("      </Points>\n      <Verts>\n");
    header(arrays + 1, "        ");
    header(arrays + 2, "        ");
    sink.raw("      </Verts>\n    </Piece>\n  </PolyData>\n");
    if (!ascii) {
        sink.raw("  <AppendedData encoding=\"base64\">\n   _");
        for (const Block& b : blocks) {
            sink.put(static_cast<long long>(b.values * b.value_bytes));  // the UInt64 byte count
            sink.end_block();
            b.emit(sink);
            sink.end_block();
        }
        sink.raw("\n  </AppendedData>\n");
    }
    sink.raw("</VTKFile>\n");
    sink.flush();
    if (!out) throw std::runtime_error("cannot write the VTK data");
}

void write_vtp_file(const std::string& path, const VtpPoints& points, VtpEncoding encoding) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path));
    try {
        write_vtp(out, points, encoding);
    } catch (const std::runtime_error&) {
        throw std::runtime_error(fmt::format("cannot write '{}'", path));
    }
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

}  // namespace sphdeck::io
