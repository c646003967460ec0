// Small decks for the reference-solver tests, written in free (comma) format.
#pragma once

#include <fmt/format.h>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "refsolver/simulation.hpp"

namespace sphdeck::test {

struct TestParticle {
    double x = 0, y = 0, z = 0, mass = 1;
    double vx = 0, vy = 0, vz = 0;  // through *INITIAL_VELOCITY on a one-node set
};

struct TestDeck {
    int idim = 3, form = 0, boxid = 0;
    double endtim = 1e-3, tssfac = 0.3, q1 = 0, q2 = 0, maxv = 1e15;
    double rho0 = 1.0, sphini = 0, cslh = 1.2, hmin = 0.2, hmax = 2.0;
    std::string eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n0,1\n";  // ideal gas, gamma 1.4, E0 = 0
    std::string extra;                                                       // more keywords
    std::vector<TestParticle> particles;

    std::string text() const {
        std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n" + fmt::format("{}\n", endtim);
        d += fmt::format("*CONTROL_TIMESTEP\n0,{}\n", tssfac);
        d += fmt::format("*CONTROL_SPH\n1,{},1e20,{},150,{},0,{}\n", boxid, idim, form, maxv);
        d += fmt::format("*CONTROL_BULK_VISCOSITY\n{},{}\n", q1, q2);
        d += fmt::format("*SECTION_SPH\n1,{},{},{},{}\n", cslh, hmin, hmax, sphini);
        d += "*PART\nfluid\n1,1,1,1\n";
        d += fmt::format("*MAT_NULL\n1,{},-1e30\n", rho0);
        d += eos + extra;
        d += "*NODE\n";
        for (std::size_t i = 0; i < particles.size(); ++i)
            d += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", i + 1, particles[i].x, particles[i].y, particles[i].z);
        d += "*ELEMENT_SPH\n";
        for (std::size_t i = 0; i < particles.size(); ++i) d += fmt::format("{},1,{:.17g}\n", i + 1, particles[i].mass);
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const TestParticle& p = particles[i];
            if (p.vx == 0 && p.vy == 0 && p.vz == 0) continue;
            d += fmt::format("*SET_NODE_LIST\n{}\n{}\n*INITIAL_VELOCITY\n{}\n{:.17g},{:.17g},{:.17g}\n", 100 + i, i + 1,
                             100 + i, p.vx, p.vy, p.vz);
        }
        return d + "*END\n";
    }
};

// Reads the deck and sets the solver up (the model must outlive the simulation only during create).
inline refsolver::Simulation::Setup solver_for(const TestDeck& deck, refsolver::RunOptions options = {}) {
    const engine::CheckResult r = engine::check_buffer(deck.text(), "test.k");
    return refsolver::Simulation::create(r.model, options);
}

inline std::string unsupported_text(const refsolver::Simulation::Setup& setup) {
    std::string all;
    for (const auto& u : setup.unsupported) all += u.what + "\n";
    return all;
}

}  // namespace sphdeck::test
