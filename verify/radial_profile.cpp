#include "verify/radial_profile.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/svg_plot.hpp"

namespace sphdeck::verify {

RadialProfile radial_profile(const ParticleState& s, int n) {
    RadialProfile out;
    out.n = n;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.active[i]) continue;
        const double radius = std::hypot(s.x[i], s.y[i]);
        out.r.push_back(radius);
        out.rho.push_back(s.rho[i]);
        out.u.push_back(radius > 0 ? (s.vx[i] * s.x[i] + s.vy[i] * s.y[i]) / radius : 0.0);
        out.p.push_back(s.p[i]);
    }
    return out;
}

double total_energy(const ParticleState& s) {
    double sum = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.active[i])
            sum += s.mass[i] * (0.5 * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]) + s.e[i]);
    return sum;
}

std::string radial_figure(const std::vector<const RadialProfile*>& runs, const RadialCurve& exact, double reach,
                          const std::string& title) {
    struct Quantity {
        const char* title;
        const char* label;
        const std::vector<double>& exact;
        std::vector<double> RadialProfile::*values;
    };
    const Quantity quantities[] = {{"density", "rho", exact.rho, &RadialProfile::rho},
                                   {"radial velocity", "u_r", exact.u, &RadialProfile::u},
                                   {"pressure", "p", exact.p, &RadialProfile::p}};
    const char* colours[] = {"#f58518", "#4c78a8"};
    std::vector<io::PlotPanel> panels;
    for (const Quantity& q : quantities) {
        io::PlotPanel panel{q.title, "r", q.label, {}, std::pair{0.0, reach}, std::nullopt};
        for (std::size_t k = 0; k < runs.size(); ++k) {
            const RadialProfile& run = *runs[k];
            std::vector<double> r, v;
            for (std::size_t i = 0; i < run.r.size(); ++i)
                if (run.r[i] <= reach) r.push_back(run.r[i]), v.push_back((run.*q.values)[i]);
            panel.series.push_back({fmt::format("SPH, {} x {} (quarter)", run.n, run.n), std::move(r), std::move(v),
                                    io::SeriesStyle::Dots, colours[k % 2]});
        }
        panel.series.push_back({exact.label, exact.r, q.exact, io::SeriesStyle::Line, "#222222"});
        panels.push_back(std::move(panel));
    }
    io::PlotOptions options;
    options.title = title;
    return io::svg_plot(panels, options);
}

}  // namespace sphdeck::verify
