// The frame shared by sphdeck's SVG figures: a grid of equal panels under an optional heading,
// the common styles, and the file writer.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace sphdeck::io {

// Where one panel goes, in SVG user units.
struct SvgBox {
    double x, y, w, h;
};

struct SvgGrid {
    std::size_t panels = 0;
    int columns = 2;  // at most; fewer when there are fewer panels
    int panel_width = 420;
    int panel_height = 300;
    std::string title;        // heading above the grid, none when empty
    std::string_view styles;  // CSS rules of the figure, after the common ones
};

// The grid of `panels` panels laid out by a figure's options (columns, panel_width, panel_height, title).
template <typename Options>
SvgGrid grid_for(std::size_t panels, const Options& options, std::string_view styles) {
    return SvgGrid{panels, options.columns, options.panel_width, options.panel_height, options.title, styles};
}

// The whole document: `draw(svg, i, box)` appends panel i.
std::string svg_panel_grid(const SvgGrid& grid,
                           const std::function<void(std::string&, std::size_t, const SvgBox&)>& draw);

// Writes `svg` to `path`; throws std::runtime_error when it cannot.
void write_text_file(const std::string& path, const std::string& svg);

}  // namespace sphdeck::io
