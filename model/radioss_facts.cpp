#include "model/radioss_facts.hpp"

namespace sphdeck::model {
namespace {
template <typename T, typename F>
const T* first_of(const std::vector<T>& items, F pred) {
    for (const T& item : items)
        if (pred(item)) return &item;
    return nullptr;
}
}  // namespace

const RadiossSphProperty* RadiossFacts::sph_property(long long id) const {
    return first_of(sph_properties, [&](const RadiossSphProperty& p) { return p.id == id; });
}
const RadiossSolidProperty* RadiossFacts::solid_property(long long id) const {
    return first_of(solid_properties, [&](const RadiossSolidProperty& p) { return p.id == id; });
}
const RadiossMaterial* RadiossFacts::material(long long id) const {
    return first_of(materials, [&](const RadiossMaterial& m) { return m.id == id; });
}
const RadiossEos* RadiossFacts::eos_of(long long mat) const {
    return first_of(eos, [&](const RadiossEos& e) { return e.material == mat; });
}
const RadiossFrame* RadiossFacts::frame(long long id, bool skew_allowed) const {
    return first_of(frames, [&](const RadiossFrame& f) { return f.id == id && (!f.skew || skew_allowed); });
}
bool RadiossFacts::has_surface(long long id) const {
    return first_of(surfaces, [&](const RadiossSurface& s) { return s.id == id; }) != nullptr;
}
const RadiossDt* RadiossFacts::time_step(DtKind kind) const {
    const RadiossDt* found = nullptr;
    for (const RadiossDt& d : time_steps)
        if (d.kind == kind && !d.in_starter) found = &d;
    return found;
}

RadiossFacts::RadiossFacts() = default;
RadiossFacts::RadiossFacts(const RadiossFacts&) = default;
RadiossFacts::RadiossFacts(RadiossFacts&&) noexcept = default;
RadiossFacts& RadiossFacts::operator=(const RadiossFacts&) = default;
RadiossFacts& RadiossFacts::operator=(RadiossFacts&&) noexcept = default;
RadiossFacts::~RadiossFacts() = default;

}  // namespace sphdeck::model
