// Histograms as a standalone SVG page: one panel per quantity, with axes, tick labels, a title,
// the sample's size, min, median and max, and the count of each bin (above its bar when it fits,
// and as a tooltip). Readable in any browser; no plotting library.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace sphdeck::io {

struct HistogramPanel {
    std::string title;           // "part 1: h / nn distance"
    std::string x_label;         // the quantity, shown under the axis
    std::vector<double> values;  // non-finite values are left out and counted
    bool integer_bins = false;   // integer data (neighbour counts): one bin per integer when they fit
};

struct SvgOptions {
    std::string title;  // heading of the page
    int columns = 2;    // panels per row
    int panel_width = 460, panel_height = 300;
    std::size_t max_bins = 24;
};

struct Bins {
    double lo = 0, width = 1;  // bin i is [lo + i*width, lo + (i+1)*width)
    std::vector<std::size_t> counts;
    std::size_t skipped = 0;  // NaN or infinite values
};

// Bins with round edges (1, 2, 2.5, 5 times a power of ten) covering every finite value; a
// sample of one distinct value gets a few bins around it, an empty one none.
Bins make_bins(std::span<const double> values, bool integer_bins, std::size_t max_bins);
// About `target` round tick values within [lo, hi]; whole numbers only when `integer`.
std::vector<double> nice_ticks(double lo, double hi, int target, bool integer = false);

std::string svg_histograms(std::span<const HistogramPanel> panels, const SvgOptions& options = {});
// Writes `path`; throws std::runtime_error naming the file when it cannot be written.
void write_svg_file(const std::string& path, std::span<const HistogramPanel> panels, const SvgOptions& options = {});

}  // namespace sphdeck::io
