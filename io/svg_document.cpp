#include "io/svg_document.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/xml_escape.hpp"

namespace sphdeck::io {

std::string svg_panel_grid(const SvgGrid& grid,
                           const std::function<void(std::string&, std::size_t, const SvgBox&)>& draw) {
    const int columns = std::max(1, std::min<int>(grid.columns, std::max<int>(1, static_cast<int>(grid.panels))));
    const int rows = static_cast<int>((grid.panels + static_cast<std::size_t>(columns) - 1) / columns);
    const double head = grid.title.empty() ? 0.0 : 36.0;
    const double width = columns * grid.panel_width, height = head + std::max(rows, 1) * grid.panel_height;
    std::string svg;
    auto out = std::back_inserter(svg);
    fmt::format_to(out,
                   "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\">\n",
                   width, height);
    svg +=
        "<style>\n"
        "text { font-family: sans-serif; fill: #222; }\n"
        ".heading { font-size: 18px; font-weight: bold; text-anchor: middle; }\n"
        ".title { font-size: 14px; font-weight: bold; text-anchor: middle; }\n"
        ".label { font-size: 12px; text-anchor: middle; }\n"
        ".xtick { font-size: 10px; text-anchor: middle; }\n"
        ".ytick { font-size: 10px; text-anchor: end; }\n"
        ".axis { stroke: #222; stroke-width: 1; fill: none; }\n"
        ".grid { stroke: #ddd; stroke-width: 1; }\n";
    svg += grid.styles;
    svg += "</style>\n";
    fmt::format_to(out, "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n", width, height);
    if (!grid.title.empty())
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"24\" class=\"heading\">{}</text>\n", width / 2,
                       xml_escape(grid.title));
    for (std::size_t i = 0; i < grid.panels; ++i) {
        const SvgBox box{static_cast<double>(static_cast<int>(i) % columns) * grid.panel_width,
                         head + static_cast<double>(static_cast<int>(i) / columns) * grid.panel_height,
                         static_cast<double>(grid.panel_width), static_cast<double>(grid.panel_height)};
        draw(svg, i, box);
    }
    svg += "</svg>\n";
    return svg;
}

void write_text_file(const std::string& path, const std::string& svg) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path));
    out.write(svg.data(), static_cast<std::streamsize>(svg.size()));
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

}  // namespace sphdeck::io
