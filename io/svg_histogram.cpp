#include "io/svg_histogram.hpp"

#include "io/svg_document.hpp"
#include "io/xml_escape.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

namespace sphdeck::io {
namespace {

// The smallest of 1, 2, 2.5, 5 times a power of ten that is at least `raw` (> 0).
double nice_step(double raw, bool integer) {
    if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        const double step = m * p;
        if (integer && step < 1.0) continue;
        if (integer && m == 2.5 && p < 10.0) continue;  // 2.5 is no integer step
        if (step >= raw * (1 - 1e-12)) return step;
    }
    return 10.0 * p;
}

std::string histogram_number(double v) {
    if (std::abs(v) < 1e-300) v = 0.0;  // no "-0"
    return fmt::format("{:.4g}", v);
}

using Box = SvgBox;

void draw_histogram_panel(std::string& svg, const HistogramPanel& panel, const Box& box, std::size_t max_bins) {
    auto out = std::back_inserter(svg);
    const Bins bins = make_bins(panel.values, panel.integer_bins, max_bins);
    std::vector<double> finite;
    for (double v : panel.values)
        if (std::isfinite(v)) finite.push_back(v);

    fmt::format_to(out, "<g>\n<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"title\">{}</text>\n", box.x + box.w / 2,
                   box.y + 20, xml_escape(panel.title));
    std::string subtitle = fmt::format("n = {}", finite.size());
    if (!finite.empty()) {
        auto mid = finite.begin() + static_cast<std::ptrdiff_t>(finite.size() / 2);
        std::nth_element(finite.begin(), mid, finite.end());
        const auto [mn, mx] = std::minmax_element(finite.begin(), finite.end());
        subtitle += fmt::format(", min {}, median {}, max {}", histogram_number(*mn), histogram_number(*mid),
                                histogram_number(*mx));
    }
    if (bins.skipped > 0) subtitle += fmt::format(", {} non-finite left out", bins.skipped);
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"subtitle\">{}</text>\n", box.x + box.w / 2, box.y + 37,
                   xml_escape(subtitle));

    const double x0 = box.x + 64, y0 = box.y + 56, pw = box.w - 64 - 24, ph = box.h - 56 - 52;
    const double ybase = y0 + ph;
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"label\">{}</text>\n", x0 + pw / 2, box.y + box.h - 10,
                   xml_escape(panel.x_label));
    fmt::format_to(out,
                   "<text x=\"{0:.1f}\" y=\"{1:.1f}\" class=\"label\" transform=\"rotate(-90 {0:.1f} {1:.1f})\">"
                   "particles</text>\n",
                   box.x + 16, y0 + ph / 2);
    if (bins.counts.empty()) {
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"label\">no values</text>\n", x0 + pw / 2,
                       y0 + ph / 2);
        fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}V{2:.1f}H{3:.1f}\" class=\"axis\"/>\n</g>\n", x0, y0, ybase,
                       x0 + pw);
        return;
    }

    const std::size_t nb = bins.counts.size();
    const double hi = bins.lo + static_cast<double>(nb) * bins.width;
    const std::size_t max_count = *std::max_element(bins.counts.begin(), bins.counts.end());
    // Count ticks up to the first round value at or above the highest bar.
    const double ystep = nice_step(static_cast<double>(std::max<std::size_t>(max_count, 1)) / 5, true);
    const double ymax = std::max(std::ceil(static_cast<double>(max_count) / ystep) * ystep, ystep);
    const std::vector<double> yticks = nice_ticks(0.0, ymax, 5, true);
    auto ypos = [&](double c) { return ybase - ph * c / ymax; };
    auto xpos = [&](double v) { return x0 + pw * (v - bins.lo) / (hi - bins.lo); };

    for (double t : yticks) {
        fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}H{2:.1f}\" class=\"grid\"/>\n", x0, ypos(t), x0 + pw);
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"ytick\">{}</text>\n", x0 - 6, ypos(t) + 4,
                       histogram_number(t));
    }
    const double bar = pw / static_cast<double>(nb), gap = bar > 4 ? 1.0 : 0.0;
    for (std::size_t i = 0; i < nb; ++i) {
        const double a = bins.lo + static_cast<double>(i) * bins.width, b = a + bins.width;
        const std::size_t c = bins.counts[i];
        const double top = ypos(static_cast<double>(c));
        fmt::format_to(out,
                       "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" class=\"bar\">"
                       "<title>[{}, {}): {}</title></rect>\n",
                       xpos(a) + gap / 2, top, std::max(bar - gap, 0.5), ybase - top, histogram_number(a),
                       histogram_number(b), c);
        const std::string label = std::to_string(c);
        if (c > 0 && bar >= 6.0 * static_cast<double>(label.size()) + 2)
            fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"count\">{}</text>\n", xpos(a) + bar / 2,
                           top - 3, label);
    }
    const bool integer_ticks = panel.integer_bins && bins.width >= 1 && bins.lo + 0.5 == std::floor(bins.lo + 0.5);
    for (double t : nice_ticks(bins.lo, hi, 6, integer_ticks)) {
        fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}v5\" class=\"axis\"/>\n", xpos(t), ybase);
        fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" class=\"xtick\">{}</text>\n", xpos(t), ybase + 18,
                       histogram_number(t));
    }
    fmt::format_to(out, "<path d=\"M{0:.1f} {1:.1f}V{2:.1f}H{3:.1f}\" class=\"axis\"/>\n</g>\n", x0, y0, ybase,
                   x0 + pw);
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target, bool integer) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
    if (!(hi > lo)) return {lo};
    const double step = nice_step((hi - lo) / std::max(target, 1), integer);
    std::vector<double> ticks;
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
        double t = k * step;
        if (std::abs(t) < step * 1e-9) t = 0.0;
        ticks.push_back(t);
    }
    return ticks;
}

Bins make_bins(std::span<const double> values, bool integer_bins, std::size_t max_bins) {
    Bins bins;
    max_bins = std::max<std::size_t>(max_bins, 5);
    double mn = INFINITY, mx = -INFINITY;
    std::size_t n = 0;
    bool integers = true;
    for (double v : values) {
        if (!std::isfinite(v)) {
            ++bins.skipped;
            continue;
        }
        ++n;
        mn = std::min(mn, v);
        mx = std::max(mx, v);
        integers = integers && v == std::floor(v);
    }
    if (n == 0) return bins;
    if (!std::isfinite(mx - mn)) {  // a span beyond a double (-1e308 to 1e308): no bin width holds it
        bins.skipped += n;
        return bins;
    }
    integers = integers && integer_bins;
    std::size_t count = 0;
    if (integers && mx - mn + 1 <= static_cast<double>(max_bins)) {
        const std::size_t span = static_cast<std::size_t>(mx - mn) + 1, pad = span < 5 ? (6 - span) / 2 : 0;
        bins.width = 1.0;
        bins.lo = mn - 0.5 - static_cast<double>(pad);
        count = span + 2 * pad;
    } else if (mx - mn <= 1e-9 * std::max(std::abs(mn), std::abs(mx))) {
        bins.width = nice_step(mn != 0 ? std::abs(mn) * 0.02 : 0.2, false);
        bins.lo = mn - 2.5 * bins.width;  // the value sits in the middle of five bins
        count = 5;
    } else {
        const double target =
            std::clamp(std::ceil(std::sqrt(static_cast<double>(n))), 5.0, static_cast<double>(max_bins));
        bins.width = nice_step((mx - mn) / target, integers);
        for (;;) {
            bins.lo = std::floor(mn / bins.width) * bins.width - (integers ? 0.5 : 0.0);
            // Compared as a double first: a count beyond size_t cannot be converted (issue 32).
            const double along = std::floor((mx - bins.lo) / bins.width);
            count = along >= 0 && along < static_cast<double>(max_bins) ? static_cast<std::size_t>(along) + 1
                                                                        : max_bins + 1;
            if (count <= max_bins) break;
            bins.width = nice_step(bins.width * 1.01, integers);
        }
    }
    bins.counts.assign(count, 0);
    for (double v : values) {
        if (!std::isfinite(v)) continue;
        const double k = std::floor((v - bins.lo) / bins.width);
        const std::size_t i = !(k > 0)                              ? 0
                              : k >= static_cast<double>(count - 1) ? count - 1
                                                                    : static_cast<std::size_t>(k);
        ++bins.counts[i];
    }
    return bins;
}

std::string svg_histograms(std::span<const HistogramPanel> panels, const SvgOptions& options) {
    const std::string_view styles =
        ".subtitle { font-size: 11px; fill: #555; text-anchor: middle; }\n"
        ".count { font-size: 9px; fill: #444; text-anchor: middle; }\n"
        ".bar { fill: #4c78a8; }\n"
        ".bar:hover { fill: #f58518; }\n";
    return svg_panel_grid(grid_for(panels.size(), options, styles),
                          [&](std::string& svg, std::size_t i, const SvgBox& box) {
                              draw_histogram_panel(svg, panels[i], box, options.max_bins);
                          });
}

void write_svg_file(const std::string& path, std::span<const HistogramPanel> panels, const SvgOptions& options) {
    write_text_file(path, svg_histograms(panels, options));
}

}  // namespace sphdeck::io
