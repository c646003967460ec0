// Line and scatter plots as a standalone SVG page: one panel per quantity, each with axes, round tick
// values, axis labels, a title and a legend. Particles are drawn as dots (one path of zero-length
// round-capped segments, compact for thousands of points), references as lines. No plotting library.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace sphdeck::io {

enum class SeriesStyle { Line, Dots, Markers };  // Markers: larger open circles, for a few data points

struct PlotSeries {
    std::string name;          // legend entry
    std::vector<double> x, y;  // same length; non-finite points are skipped (and break a line)
    SeriesStyle style = SeriesStyle::Line;
    std::string colour;  // CSS colour; empty: the next of a fixed palette
};

struct PlotPanel {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    std::optional<std::pair<double, double>> x_range, y_range;  // default: the data's range, padded
};

struct PlotOptions {
    std::string title;  // heading of the page
    int columns = 2;
    int panel_width = 520, panel_height = 340;
};

std::string svg_plot(std::span<const PlotPanel> panels, const PlotOptions& options = {});
// Writes `path`; throws std::runtime_error naming the file when it cannot be written.
void write_svg_plot_file(const std::string& path, std::span<const PlotPanel> panels, const PlotOptions& options = {});

}  // namespace sphdeck::io
