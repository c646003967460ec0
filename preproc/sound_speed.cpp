#include "preproc/sound_speed.hpp"

#include <cmath>

namespace sphdeck::preproc {

double murnaghan_sound_speed(double gamma, double k0, double rho0) {
    const double c2 = rho0 > 0 ? gamma * k0 / rho0 : 0.0;
    return c2 > 0 ? std::sqrt(c2) : 0.0;
}

double linear_polynomial_sound_speed(const double (&c)[7], double e0, double rho0) {
    const double p0 = c[0] + c[4] * e0;
    const double c2 = rho0 > 0 ? (c[1] + c[5] * e0 + c[4] * p0) / rho0 : 0.0;
    return c2 > 0 ? std::sqrt(c2) : 0.0;
}

double elastic_sound_speed(double young, double poisson, double rho0) {
    if (rho0 <= 0 || young <= 0 || poisson <= -1 || poisson >= 0.5) return 0;
    return std::sqrt(young * (1 - poisson) / ((1 + poisson) * (1 - 2 * poisson) * rho0));
}

namespace {

const model::KeywordRecord* record_of(const model::Model& m, std::optional<std::size_t> index) {
    return index && *index < m.records.size() ? &m.records[*index] : nullptr;
}

double sound_number(const model::KeywordRecord* r, std::string_view name, double fallback = 0.0) {
    const model::FieldRecord* f = r ? r->field(name) : nullptr;
    return f && f->valid ? f->number : fallback;
}

// The EOS bulk sound speed at the reference state; 0 with a note when unknown.
double eos_sound_speed(const model::Model& m, const model::Eos& eos, double rho0, std::string& note) {
    const model::KeywordRecord* r = record_of(m, eos.record);
    double c = 0;
    if (!r) {
        note = eos.keyword + " is not decoded: its sound speed is unknown";
        return 0;
    }
    if (eos.keyword == "*EOS_MURNAGHAN") {
        c = murnaghan_sound_speed(sound_number(r, "GAMMA"), sound_number(r, "K0"), rho0);
    } else if (eos.keyword == "*EOS_GRUNEISEN") {
        c = sound_number(r, "C");
    } else if (eos.keyword == "*EOS_LINEAR_POLYNOMIAL") {
        const double coefficients[7] = {sound_number(r, "C0"), sound_number(r, "C1"), sound_number(r, "C2"),
                                        sound_number(r, "C3"), sound_number(r, "C4"), sound_number(r, "C5"),
                                        sound_number(r, "C6")};
        c = linear_polynomial_sound_speed(coefficients, sound_number(r, "E0"), rho0);
    } else {
        note = eos.keyword + ": no sound speed formula";
        return 0;
    }
    if (!(c > 0)) note = eos.keyword + " " + eos.id + " gives no positive sound speed at the reference state";
    return c > 0 ? c : 0.0;
}

}  // namespace

SoundSpeed sound_speed(const model::Model& m, const model::Material* material, const model::Eos* eos) {
    SoundSpeed out;
    if (!material) {
        out.note = "no material: no sound speed";
        return out;
    }
    const double rho0 = material->density.value;
    if (!(rho0 > 0)) {
        out.note = "material " + material->id + " has no positive density: no sound speed";
        return out;
    }
    const model::KeywordRecord* r = record_of(m, material->record);
    const std::string& kw = material->keyword;
    const bool elastic = kw == "*MAT_ELASTIC" || kw == "*MAT_PLASTIC_KINEMATIC" || kw == "*MAT_JOHNSON_COOK";
    double young = sound_number(r, "E"), poisson = sound_number(r, "PR"), shear = 0;
    if (kw == "*MAT_JOHNSON_COOK")
        shear = sound_number(r, "G");
    else if (elastic && young > 0 && poisson > -1)
        shear = young / (2 * (1 + poisson));

    if (eos) {
        const double bulk = eos_sound_speed(m, *eos, rho0, out.note);
        if (bulk <= 0) return out;
        out.c = std::sqrt(bulk * bulk + 4.0 * shear / (3.0 * rho0));
        out.source = eos->keyword + (shear > 0 ? " + " + kw + " shear" : "");
        if (!elastic && kw != "*MAT_NULL") out.note = kw + ": shear stiffness not known, EOS bulk sound speed used";
        return out;
    }
    if (kw == "*MAT_ELASTIC" && r && r->has_option("FLUID")) {
        const double bulk = sound_number(r, "K");
        out.c = bulk > 0 ? std::sqrt(bulk / rho0) : 0.0;
    } else if (elastic) {
        out.c = elastic_sound_speed(young, poisson, rho0);
    } else if (kw == "*MAT_NULL") {
        out.note = "*MAT_NULL without an equation of state: no sound speed";
        return out;
    } else {
        out.note = kw + ": no sound speed formula";
        return out;
    }
    if (out.c > 0)
        out.source = kw;
    else
        out.note = kw + " " + material->id + ": no positive sound speed from its moduli";
    return out;
}

}  // namespace sphdeck::preproc
