// `sphdeck run --out`: the .vtp snapshots carry velocity as one 3-component array (and the stress
// tensor for *MAT_ELASTIC), and particles.pvd lists them with the physical time of each, the times
// of the run (history.csv). Read back by Python's standard library; each .vtp also by VTK's own
// reader when an interpreter with VTK is installed (validate_vtp, test_io_writers.cpp).
#include <doctest/doctest.h>

#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "run_sphdeck.hpp"
#include "test_refsolver_decks.hpp"

namespace sphdeck::test {
std::string validate_vtp(const std::string& path, std::size_t points, std::string* names);
bool python_available();
}  // namespace sphdeck::test

using namespace sphdeck::test;

namespace {

// argv: out folder, particle count, "stress" or "no-stress". Checks particles.pvd (a Collection,
// timesteps strictly increasing, each equal to the time history.csv gives for the snapshot's step)
// and every .vtp it lists: a 3-component "velocity" with component names, no vx/vy/vz arrays, a
// 6-component "stress" exactly when asked, and sum(mass * velocity) over the active particles
// equal to the momentum history.csv gives for that step. Prints the number of snapshots.
constexpr const char* series_check_py = R"PY(
import base64, csv, os, re, struct, sys, xml.etree.ElementTree as ET
out, n, want_stress = sys.argv[1], int(sys.argv[2]), sys.argv[3] == 'stress'
history = {}
with open(os.path.join(out, 'history.csv')) as f:
    for row in csv.DictReader(f):
        history[int(row['step'])] = row
root = ET.parse(os.path.join(out, 'particles.pvd')).getroot()
assert root.tag == 'VTKFile' and root.get('type') == 'Collection', 'not a Collection'
sets = root.findall('./Collection/DataSet')
assert len(sets) >= 2, 'expected several snapshots, got %d' % len(sets)
times = [float(d.get('timestep')) for d in sets]
assert all(a < b for a, b in zip(times, times[1:])), 'timesteps not increasing: %r' % times
sizes = {'Int64': ('q', 8), 'UInt32': ('I', 4), 'Float64': ('d', 8)}
for d, t in zip(sets, times):
    name = d.get('file')
    step = int(re.fullmatch(r'particles_(\d+)\.vtp', name).group(1))
    assert float(history[step]['time']) == t, '%s: timestep %r, history time %s' % (name, t, history[step]['time'])
    vtp = ET.parse(os.path.join(out, name)).getroot()
    order = {'LittleEndian': '<', 'BigEndian': '>'}[vtp.get('byte_order')]
    blob = vtp.find('AppendedData').text.strip()[1:]
    def values(a):
        off, hlen = int(a.get('offset')), 4 * ((8 + 2) // 3)
        nbytes = struct.unpack(order + 'Q', base64.b64decode(blob[off:off + hlen]))[0]
        data = base64.b64decode(blob[off + hlen:off + hlen + 4 * ((nbytes + 2) // 3)])
        code, size = sizes[a.get('type')]
        return struct.unpack(order + code * (nbytes // size), data)
    arrays = {a.get('Name'): a for a in vtp.findall('./PolyData/Piece/PointData/DataArray')}
    assert not {'vx', 'vy', 'vz'} & set(arrays), 'separate velocity components remain'
    v = arrays['velocity']
    assert v.get('NumberOfComponents') == '3', 'velocity components ' + str(v.get('NumberOfComponents'))
    assert [v.get('ComponentName%d' % k) for k in range(3)] == ['X', 'Y', 'Z'], 'velocity component names'
    if want_stress:
        s = arrays['stress']
        assert s.get('NumberOfComponents') == '6', 'stress components ' + str(s.get('NumberOfComponents'))
        assert len(values(s)) == 6 * n, 'stress values'
    else:
        assert 'stress' not in arrays, 'stress written for a fluid'
    vel, mass, active = values(v), values(arrays['mass']), values(arrays['active'])
    assert len(vel) == 3 * n and len(mass) == n, 'velocity values'
    for k, axis in enumerate('xyz'):
        p = sum(mass[i] * vel[3 * i + k] for i in range(n) if active[i])
        scale = sum(abs(mass[i] * vel[3 * i + k]) for i in range(n)) + 1e-300
        want = float(history[step]['momentum_' + axis])
        assert abs(p - want) <= 1e-12 * scale, '%s: momentum %s %r, history %r' % (name, axis, p, want)
print(len(sets))
)PY";

// Runs the series check; "" when it passes, else its output.
std::string check_series(const TempDir& dir, std::size_t particles, bool stress) {
    const std::string script = dir.write("check_series.py", series_check_py);
    const std::string log = (dir.path() / "series.txt").string();
    const std::string command =
        fmt::format("python3 '{}' '{}' {} {} > '{}' 2>&1", script, (dir.path() / "out").string(), particles,
                    stress ? "stress" : "no-stress", log);
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return status == 0 ? "" : text;
}

}  // namespace

TEST_CASE("refsolver cli: run writes particles.pvd with the snapshot times and a velocity vector") {
    if (!python_available()) return;
    TempDir dir;
    const std::string deck = std::string(SPHDECK_SOURCE_DIR) + "/decks/run/water_column_2d.k";
    const Run r = run_sphdeck(dir, "run '" + deck + "' --end-time 0.004 --every 10 --out out --quiet");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.out.find("particles.pvd") != std::string::npos);
    CHECK(check_series(dir, 800, false) == "");
    CHECK(validate_vtp((dir.path() / "out" / "particles_000010.vtp").string(), 800, nullptr) == "");
}

TEST_CASE("refsolver cli: run snapshots of a *MAT_ELASTIC deck carry the stress tensor") {
    if (!python_available()) return;
    TestDeck deck;
    deck.idim = 2;
    deck.eos.clear();
    const double dx = 0.125;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) deck.particles.push_back({i * dx, j * dx, 0, dx * dx, 0.0078125 * j, 0, 0});
    deck.endtim = 0.05;
    deck.maxv = 1e6;
    std::string text = deck.text();
    const std::string fluid = fmt::format("*MAT_NULL\n1,{},-1e30\n", deck.rho0);
    REQUIRE(text.find(fluid) != std::string::npos);
    text.replace(text.find(fluid), fluid.size(), fmt::format("*MAT_ELASTIC\n1,{},1.0,0.3\n", deck.rho0));
    const std::string part = "*PART\nfluid\n1,1,1,1\n";
    REQUIRE(text.find(part) != std::string::npos);
    text.replace(text.find(part), part.size(), "*PART\nsolid\n1,1,1\n");
    TempDir dir;
    dir.write("elastic.k", text);
    const Run r = run_sphdeck(dir, "run elastic.k --every 5 --out out --quiet");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(check_series(dir, 16, true) == "");
    std::string names;
    CHECK(validate_vtp((dir.path() / "out" / "particles_000000.vtp").string(), 16, &names) == "");
    CHECK(names.find("stress") != std::string::npos);
    CHECK(names.find("velocity") != std::string::npos);
}
