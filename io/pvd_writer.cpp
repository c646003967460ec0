#include "io/pvd_writer.hpp"

#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

#include "io/xml_escape.hpp"

namespace sphdeck::io {

void write_pvd_file(const std::string& path, const std::vector<PvdEntry>& entries) {
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (const PvdEntry& e : entries)
        text += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
                            xml_escape(e.file));
    text += "  </Collection>\n</VTKFile>\n";
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path));
    out << text;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

}  // namespace sphdeck::io
