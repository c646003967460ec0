#include "io/svg_plot.hpp"

#include "io/svg_histogram.hpp"  // nice_ticks
#include "io/svg_document.hpp"
#include "io/xml_escape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

namespace sphdeck::io {
namespace {

constexpr std::array<const char*, 6> palette = {"#4c78a8", "#e45756", "#54a24b", "#f58518", "#b279a2", "#222222"};

std::string plot_number(double v) {
    if (std::abs(v) < 1e-300) v = 0.0;  // no "-0"
    return fmt::format("{:.4g}", v);
}

struct Range {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    // An empty range becomes [0, 1]; a single value gets room around it; others 4 % padding.
    Range padded() const {
        if (!(hi >= lo)) return {0.0, 1.0};
        if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
            const double d = lo != 0 ? std::abs(lo) * 0.1 : 1.0;
            return {lo - d, hi + d};
        }
        const double d = 0.04 * (hi - lo);
        return {lo - d, hi + d};
    }
};

using Box = SvgBox;

void draw_plot_panel(std::string& svg, const PlotPanel& panel, const Box& box, std::size_t first_colour) {
    auto out = std::back_inserter(svg);
    Range xr, yr;
    for (const PlotSeries& s : panel.series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            if (panel.x_range && (s.x[i] < panel.x_range->first || s.x[i] > panel.x_range->second)) continue;
            xr.add(s.x[i]);
            yr.add(s.y[i]);
        }
    }
    xr = panel.x_range ? Range{panel.x_range->first, panel.x_range->second} : xr.padded();
    yr = panel.y_range ? Range{panel.y_range->first, panel.y_range->second} : yr.padded();
    if (!(xr.hi > xr.lo)) xr = Range{xr.lo - 1, xr.lo + 1};
    if (!(yr.hi > yr.lo)) yr = Range{yr.lo - 1, yr.lo + 1};

    const double x0 = box.x + 70, y0 = box.y + 40, pw = box.w - 70 - 20, ph = box.h - 40 - 56;
    auto xpos = [&](double v) { return x0 + pw * (v - xr.lo) / (xr.hi - xr.lo); };
    auto ypos = [&](double v) { return y0 + ph - ph * (v - yr.lo) / (yr.hi - yr.lo); };
    auto inside = [&](double x, double y) { return x >= xr.lo && x <= xr.hi && y >= yr.lo && y <= yr.hi; };

    fmt::format_to(out, "<g>\n<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"title\">{}</text>\n", x0 + pw / 2, box.y + 22,
                   xml_escape(panel.title));
    for (double t : nice_ticks(yr.lo, yr.hi, 5)) {
        fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}H{2:.1f}\" class=\"grid\"/>\n", x0, ypos(t), x0 + pw);
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"ytick\">{}</text>\n", x0 - 6, ypos(t) + 4,
                       plot_number(t));
    }
    for (double t : nice_ticks(xr.lo, xr.hi, 6)) {
        fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}v5\" class=\"axis\"/>\n", xpos(t), y0 + ph);
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"xtick\">{}</text>\n", xpos(t), y0 + ph + 18,
                       plot_number(t));
    }
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"label\">{}</text>\n", x0 + pw / 2, box.y + box.h - 14,
                   xml_escape(panel.x_label));
    fmt::format_to(out,
                   "<text x=\"{0:.1f}\" y=\"{1:.1f}\" class=\"label\" transform=\"rotate(-90 {0:.1f} {1:.1f})\">"
                   "{2}</text>\n",
                   box.x + 16, y0 + ph / 2, xml_escape(panel.y_label));

    // Series, clipped to the plot area; then the legend in the top-right corner.
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
        const PlotSeries& s = panel.series[k];
        const std::string colour = s.colour.empty() ? palette[(first_colour + k) % palette.size()] : s.colour;
        const std::size_t n = std::min(s.x.size(), s.y.size());
        std::string d;
        auto dd = std::back_inserter(d);
        bool pen_down = false;
        for (std::size_t i = 0; i < n; ++i) {
            const double x = s.x[i], y = s.y[i];
            if (!std::isfinite(x) || !std::isfinite(y) || (s.style != SeriesStyle::Line && !inside(x, y))) {
                pen_down = false;
                continue;
            }
            const double px = std::clamp(xpos(x), x0 - 2, x0 + pw + 2), py = std::clamp(ypos(y), y0 - 2, y0 + ph + 2);
            if (s.style == SeriesStyle::Line) {
                fmt::format_to(dd, "{}{:.1f} {:.1f}", pen_down ? "L" : "M", px, py);
                pen_down = true;
            } else if (s.style == SeriesStyle::Dots) {
                fmt::format_to(dd, "M{:.1f} {:.1f}h0", px, py);
            } else {
                fmt::format_to(out, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" class=\"marker\" stroke=\"{}\"/>\n",
                               px, py, colour);
            }
        }
        if (!d.empty())
            fmt::format_to(out, "<path d=\"{}\" class=\"{}\" stroke=\"{}\"/>\n", d,
                           s.style == SeriesStyle::Line ? "line" : "dots", colour);
        const double ly = y0 + 14 + 16 * static_cast<double>(k), lx = x0 + pw - 150;
        if (s.style == SeriesStyle::Line)
            fmt::format_to(out, "<path d=\"M{:.1f} {:.1f}h18\" class=\"line\" stroke=\"{}\"/>\n", lx, ly - 4, colour);
        else if (s.style == SeriesStyle::Dots)
            fmt::format_to(out, "<path d=\"M{:.1f} {:.1f}h0\" class=\"dots\" stroke=\"{}\"/>\n", lx + 9, ly - 4,
                           colour);
        else
            fmt::format_to(out, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" class=\"marker\" stroke=\"{}\"/>\n",
                           lx + 9, ly - 4, colour);
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"legend\">{}</text>\n", lx + 24, ly,
                       xml_escape(s.name));
    }
    fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}V{2:.1f}H{3:.1f}\" class=\"axis\"/>\n</g>\n", x0, y0, y0 + ph,
                   x0 + pw);
}

}  // namespace

std::string svg_plot(std::span<const PlotPanel> panels, const PlotOptions& options) {
    const std::string_view styles =
        ".legend { font-size: 11px; }\n"
        ".line { fill: none; stroke-width: 1.6; }\n"
        ".dots { fill: none; stroke-width: 3; stroke-linecap: round; }\n"
        ".marker { fill: white; stroke-width: 1.6; }\n";
    return svg_panel_grid(grid_for(panels.size(), options, styles),
                          [&](std::string& svg, std::size_t i, const SvgBox& box) {
                              draw_plot_panel(svg, panels[i], box, 0);
                          });
}

void write_svg_plot_file(const std::string& path, std::span<const PlotPanel> panels, const PlotOptions& options) {
    write_text_file(path, svg_plot(panels, options));
}

}  // namespace sphdeck::io
