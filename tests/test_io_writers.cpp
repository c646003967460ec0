// io/: the CSV, VTK XML PolyData and SVG writers. Written files are read back by Python's
// standard library (XML well-formedness, counts of values per array) and, where an interpreter
// with VTK is installed (Debian's python3-vtk9 or ParaView's pvpython), by VTK's own
// vtkXMLPolyDataReader, the reader ParaView uses.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/csv_writer.hpp"
#include "io/svg_histogram.hpp"
#include "io/vtp_writer.hpp"
#include "test_support.hpp"

namespace sphdeck::test {

namespace {

// Checks a .vtp: well-formed XML, one PolyData piece with NumberOfPoints = NumberOfVerts = argv[2],
// every DataArray holding the number of values its place requires (ASCII tokens, or the byte
// count of an appended base64 block, decoded), and prints the point-data array names.
constexpr const char* vtp_check_py = R"PY(
import base64, struct, sys, xml.etree.ElementTree as ET
path, n = sys.argv[1], int(sys.argv[2])
root = ET.parse(path).getroot()
assert root.tag == 'VTKFile' and root.get('type') == 'PolyData', 'not a PolyData VTKFile'
header = {'UInt32': 'I', 'UInt64': 'Q'}[root.get('header_type', 'UInt32')]
order = {'LittleEndian': '<', 'BigEndian': '>'}[root.get('byte_order')]
sizes = {'Int32': 4, 'UInt32': 4, 'Int64': 8, 'UInt64': 8, 'Float32': 4, 'Float64': 8}
pieces = root.findall('./PolyData/Piece')
assert len(pieces) == 1, 'expected one Piece'
piece = pieces[0]
assert int(piece.get('NumberOfPoints')) == n, 'NumberOfPoints ' + piece.get('NumberOfPoints')
assert int(piece.get('NumberOfVerts')) == n, 'NumberOfVerts ' + piece.get('NumberOfVerts')
appended = root.find('AppendedData')
blob = None
if appended is not None:
    assert appended.get('encoding') == 'base64', 'appended data not base64'
    text = appended.text.strip()
    assert text[0] == '_', 'appended data must start with _'
    blob = text[1:]
def count(a):
    if a.get('format') == 'ascii':
        return len((a.text or '').split())
    assert a.get('format') == 'appended' and blob is not None, 'unknown format ' + str(a.get('format'))
    off, hlen = int(a.get('offset')), 4 * ((struct.calcsize(header) + 2) // 3)
    nbytes = struct.unpack(order + header, base64.b64decode(blob[off:off + hlen], validate=True))[0]
    data = base64.b64decode(blob[off + hlen:off + hlen + 4 * ((nbytes + 2) // 3)], validate=True)
    assert len(data) == nbytes, 'short block'
    return nbytes // sizes[a.get('type')]
want = {}
for a in piece.findall('./PointData/DataArray'):
    want[a] = n * int(a.get('NumberOfComponents', '1'))
points = piece.findall('./Points/DataArray')
assert len(points) == 1 and points[0].get('NumberOfComponents') == '3', 'Points need 3 components'
want[points[0]] = 3 * n
verts = {a.get('Name'): a for a in piece.findall('./Verts/DataArray')}
want[verts['connectivity']] = n
want[verts['offsets']] = n
for a, expected in want.items():
    got = count(a)
    assert got == expected, '%s: %d values, expected %d' % (a.get('Name'), got, expected)
print(' '.join(sorted(a.get('Name') for a in piece.findall('./PointData/DataArray'))))
)PY";

// Reads the file with VTK's XML reader: no error event, the points, verts and arrays expected.
constexpr const char* vtp_vtk_py = R"PY(
import sys, vtk
path, n, names = sys.argv[1], int(sys.argv[2]), [a for a in sys.argv[3].split(',') if a]
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(path)
errors = []
reader.AddObserver('ErrorEvent', lambda o, e: errors.append(e))
reader.GetExecutive().AddObserver('ErrorEvent', lambda o, e: errors.append(e))
reader.Update()
out = reader.GetOutput()
assert not errors, 'VTK reported errors'
assert out.GetNumberOfPoints() == n, 'points %d' % out.GetNumberOfPoints()
assert out.GetNumberOfVerts() == n, 'verts %d' % out.GetNumberOfVerts()
for name in names:
    a = out.GetPointData().GetArray(name)
    assert a is not None and a.GetNumberOfTuples() == n, 'array ' + name
print('vtk', vtk.vtkVersion.GetVTKVersion())
)PY";

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool succeeds(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()) == 0; }

}  // namespace

bool python_available() { return succeeds("python3 -c 'import xml.etree.ElementTree'"); }

// An interpreter that can `import vtk`, or "" (then the VTK reader check is skipped).
std::string vtk_python() {
    for (const char* candidate : {"python3", "/usr/bin/python3", "pvpython"})
        if (succeeds(std::string(candidate) + " -c 'import vtk'")) return candidate;
    return "";
}

// Validates the .vtp at `path` (see vtp_check_py; also vtp_vtk_py when VTK is installed).
// Returns "" when valid, else what went wrong; `names` receives the point-data array names.
std::string validate_vtp(const std::string& path, std::size_t points, std::string* names) {
    TempDir dir;
    const std::string script = dir.write("check_vtp.py", vtp_check_py), out = (dir.path() / "out.txt").string();
    const std::string command =
        "python3 '" + script + "' '" + path + "' " + std::to_string(points) + " > '" + out + "' 2>&1";
    if (std::system(command.c_str()) != 0) return "structure check failed: " + slurp(out);
    std::string found = slurp(out);
    while (!found.empty() && (found.back() == '\n' || found.back() == '\r')) found.pop_back();
    if (names) *names = found;
    const std::string py = vtk_python();
    if (py.empty()) {
        MESSAGE("no Python with VTK (python3-vtk9 or pvpython): VTK reader check skipped");
        return "";
    }
    std::string list = found;
    for (char& c : list)
        if (c == ' ') c = ',';
    const std::string vtk_script = dir.write("read_vtp.py", vtp_vtk_py);
    const std::string vtk_command =
        py + " '" + vtk_script + "' '" + path + "' " + std::to_string(points) + " '" + list + "' > '" + out + "' 2>&1";
    if (std::system(vtk_command.c_str()) != 0) return "VTK reader: " + slurp(out);
    return "";
}

// Whether the file is well-formed XML (Python's parser).
bool xml_well_formed(const std::string& path) {
    return succeeds("python3 -c 'import sys, xml.etree.ElementTree as ET; ET.parse(sys.argv[1])' '" + path + "'");
}

}  // namespace sphdeck::test

using namespace sphdeck;

namespace {

struct Sample {
    std::vector<long long> id{11, 12, 13, 14, 15};
    std::vector<double> x{0.0, 0.1, 0.2, 1.0 / 3.0, -2.5e-7}, y{1, 2, 3, 4, 5}, z{0, 0, 0, 0, 1e300};
    std::vector<double> h{0.018, 0.018, 0.25, NAN, 1e-5};
    std::vector<std::uint32_t> neighbours{0, 7, 20, 4294967295u, 12};

    std::vector<io::Column> columns() const {
        return {{"id", std::span<const long long>(id)},
                {"h", std::span<const double>(h)},
                {"neighbours", std::span<const std::uint32_t>(neighbours)}};
    }
};

std::vector<std::string> split_lines(const std::string& text, const std::string& end) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t stop = text.find(end, start);
        if (stop == std::string::npos) stop = text.size();
        lines.push_back(text.substr(start, stop - start));
        start = stop + end.size();
    }
    return lines;
}

}  // namespace

TEST_CASE("io: csv has a header row, CRLF records and reals that read back exactly") {
    const Sample s;
    std::vector<io::Column> columns = s.columns();
    columns.insert(columns.begin() + 1, {"x", std::span<const double>(s.x)});
    std::ostringstream out;
    io::write_csv(out, columns);
    const std::string text = out.str();
    CHECK(text.find('\n') == text.find("\r\n") + 1);
    const auto lines = split_lines(text, "\r\n");
    REQUIRE(lines.size() == 6);
    CHECK(lines[0] == "id,x,h,neighbours");
    CHECK(lines[1] == "11,0,0.017999999999999999,0");
    CHECK(lines[4] == "14,0.33333333333333331,nan,4294967295");
    CHECK(std::stod(lines[4].substr(3)) == 1.0 / 3.0);
    CHECK(std::stod(lines[5].substr(3)) == -2.5e-7);
}

TEST_CASE("io: csv quotes only the fields that need it and rejects ragged columns") {
    CHECK(io::csv_field("nn_distance") == "nn_distance");
    CHECK(io::csv_field("a,b") == "\"a,b\"");
    CHECK(io::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    CHECK(io::csv_field("two\nlines") == "\"two\nlines\"");
    CHECK(io::csv_field(" padded") == "\" padded\"");

    const std::vector<long long> three{1, 2, 3};
    const std::vector<double> two{1.0, 2.0};
    const std::vector<io::Column> ragged{{"a", std::span<const long long>(three)}, {"b", std::span<const double>(two)}};
    std::ostringstream out;
    CHECK_THROWS_AS(io::write_csv(out, ragged), std::invalid_argument);
    CHECK_THROWS_AS(io::write_csv_file("/nonexistent-folder/x.csv", ragged), std::runtime_error);
}

TEST_CASE("io: base64 follows RFC 4648") {
    auto b64 = [](std::string_view s) {
        return io::base64({reinterpret_cast<const unsigned char*>(s.data()), s.size()});
    };
    CHECK(b64("") == "");
    CHECK(b64("f") == "Zg==");
    CHECK(b64("fo") == "Zm8=");
    CHECK(b64("foo") == "Zm9v");
    CHECK(b64("foob") == "Zm9vYg==");
    CHECK(b64("foobar") == "Zm9vYmFy");
}

TEST_CASE("io: vtp in ASCII is well-formed PolyData with vertex cells and typed point data") {
    const Sample s;
    io::VtpPoints points{s.x, s.y, s.z, s.columns()};
    std::ostringstream out;
    io::write_vtp(out, points);
    const std::string text = out.str();
    CHECK(text.find("<VTKFile type=\"PolyData\" version=\"1.0\"") != std::string::npos);
    CHECK(text.find("NumberOfPoints=\"5\" NumberOfVerts=\"5\"") != std::string::npos);
    CHECK(text.find("<DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n11 12 13 14 15\n") != std::string::npos);
    CHECK(text.find("<DataArray type=\"UInt32\" Name=\"neighbours\"") != std::string::npos);
    CHECK(text.find("<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"") != std::string::npos);
    CHECK(text.find("0.3333333333333333 4 0") != std::string::npos);  // shortest round-trip digits
    CHECK(text.find("Name=\"offsets\" format=\"ascii\">\n1 2 3 4 5\n") != std::string::npos);

    if (!test::python_available()) {
        MESSAGE("python3 not found: XML checks skipped");
        return;
    }
    test::TempDir dir;
    const std::string path = (dir.path() / "points.vtp").string();
    io::write_vtp_file(path, points);
    std::string names;
    CHECK(test::validate_vtp(path, 5, &names) == "");
    CHECK(names == "h id neighbours");
}

TEST_CASE("io: vtp with appended base64 data is well-formed and its blocks hold every value") {
    const Sample s;
    io::VtpPoints points{s.x, s.y, s.z, s.columns()};
    std::ostringstream out;
    io::write_vtp(out, points, io::VtpEncoding::Base64);
    const std::string text = out.str();
    CHECK(text.find("<AppendedData encoding=\"base64\">") != std::string::npos);
    CHECK(text.find("format=\"appended\" offset=\"0\"") != std::string::npos);
    // The first block: the UInt64 byte count 40 (5 Int64), encoded on its own, then the ids.
    const std::size_t at = text.find('_', text.find("<AppendedData")) + 1;
    CHECK(text.substr(at, 12) == "KAAAAAAAAAA=");

    if (!test::python_available()) return;
    test::TempDir dir;
    const std::string path = (dir.path() / "points.vtp").string();
    io::write_vtp_file(path, points, io::VtpEncoding::Base64);
    CHECK(test::validate_vtp(path, 5, nullptr) == "");

    // No points at all is still a valid file.
    const std::vector<double> none;
    const std::string empty = (dir.path() / "empty.vtp").string();
    io::write_vtp_file(empty, io::VtpPoints{none, none, none, {}}, io::VtpEncoding::Base64);
    CHECK(test::validate_vtp(empty, 0, nullptr) == "");
}

TEST_CASE("io: vtp rejects arrays of the wrong length and unwritable paths") {
    const Sample s;
    const std::vector<double> short_h{1.0};
    io::VtpPoints points{s.x, s.y, s.z, {{"h", std::span<const double>(short_h)}}};
    std::ostringstream out;
    CHECK_THROWS_AS(io::write_vtp(out, points), std::invalid_argument);
    CHECK_THROWS_AS(io::write_vtp_file("/nonexistent-folder/x.vtp", io::VtpPoints{s.x, s.y, s.z, {}}),
                    std::runtime_error);
}

TEST_CASE("io: histogram bins of extreme values convert no double out of range (issue 32)") {
    // Values 1e300 apart with a few tiny ones: the first bin width gives more bins than size_t holds.
    const std::vector<double> wide{1e-300, 2e-300, 1e300};
    const io::Bins w = io::make_bins(wide, false, 24);
    std::size_t total = 0;
    for (std::size_t c : w.counts) total += c;
    CHECK(total == 3);
    CHECK(w.counts.size() <= 24);
    // A span beyond a double: nothing binned, every value counted as skipped, and no endless widening.
    const std::vector<double> beyond{-1e308, 1e308};
    const io::Bins b = io::make_bins(beyond, false, 24);
    CHECK(b.counts.empty());
    CHECK(b.skipped == 2);
}

TEST_CASE("io: histogram bins have round edges and cover every finite value") {
    const std::vector<double> values{1.0, 1.05, 1.2, 1.21, 1.5, 2.0, NAN, INFINITY};
    const io::Bins b = io::make_bins(values, false, 24);
    CHECK(b.skipped == 2);
    std::size_t total = 0;
    for (std::size_t c : b.counts) total += c;
    CHECK(total == 6);
    CHECK(b.lo <= 1.0);
    CHECK(b.lo + static_cast<double>(b.counts.size()) * b.width > 2.0);
    CHECK(b.counts.size() <= 24);

    // Integer data: one bin per integer, centred on it.
    const std::vector<double> counts{7, 20, 20, 12, 12, 20};
    const io::Bins ib = io::make_bins(counts, true, 24);
    CHECK(ib.width == 1.0);
    CHECK(ib.lo == 6.5);
    REQUIRE(ib.counts.size() == 14);
    CHECK(ib.counts.front() == 1);
    CHECK(ib.counts.back() == 3);

    // One distinct value: it sits in the middle bin of five.
    const std::vector<double> same(10, 1.2);
    const io::Bins sb = io::make_bins(same, false, 24);
    REQUIRE(sb.counts.size() == 5);
    CHECK(sb.counts[2] == 10);

    CHECK(io::make_bins(std::vector<double>{}, false, 24).counts.empty());
    const std::vector<double> ticks = io::nice_ticks(0.0, 1.0, 5);
    REQUIRE(ticks.size() == 6);
    for (std::size_t i = 0; i < ticks.size(); ++i) CHECK(ticks[i] == doctest::Approx(0.2 * static_cast<double>(i)));
    CHECK(io::nice_ticks(6.5, 20.5, 6, true) == std::vector<double>{10.0, 15.0, 20.0});
}

TEST_CASE("io: svg histograms are well-formed with one titled panel per quantity") {
    std::vector<io::HistogramPanel> panels{
        {"part 1: h / nn distance", "h / nn distance", {1.2, 1.2, 1.25, 1.3, NAN}, false},
        {"part 1: neighbours", "neighbours", {7, 12, 20, 20}, true},
        {"part <2> & \"friends\"", "nothing", {}, false},
    };
    io::SvgOptions options;
    options.title = "sphdeck smooth a&b.k";
    const std::string svg = io::svg_histograms(panels, options);
    CHECK(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\"") != std::string::npos);
    CHECK(svg.find("part 1: h / nn distance") != std::string::npos);
    CHECK(svg.find("part &lt;2&gt; &amp; &quot;friends&quot;") != std::string::npos);
    CHECK(svg.find("a&amp;b.k") != std::string::npos);
    CHECK(svg.find("1 non-finite left out") != std::string::npos);
    CHECK(svg.find("no values") != std::string::npos);
    CHECK(svg.find("<title>[19.5, 20.5): 2</title>") != std::string::npos);
    CHECK(svg.find(">particles</text>") != std::string::npos);

    if (!test::python_available()) return;
    test::TempDir dir;
    const std::string path = (dir.path() / "plot.svg").string();
    io::write_svg_file(path, panels, options);
    CHECK(test::xml_well_formed(path));
}
