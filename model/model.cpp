#include "model/model.hpp"

#include <charconv>

namespace sphdeck::model {

const FieldRecord* KeywordRecord::field(std::string_view name) const {
    for (const auto& row : rows)
        for (const auto& f : row)
            if (f.name == name) return &f;
    return nullptr;
}

bool KeywordRecord::has_option(std::string_view suffix) const {
    for (auto o : options)
        if (o == suffix) return true;
    return false;
}

void compact_bulk_ids(Model& model) {
    model.nodes.id.compact(), model.particles.node.compact(), model.particles.part.compact();
}

Id normalise_id(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
    long long n = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec == std::errc() && end == text.data() + text.size()) return std::to_string(n);
    return Id(text);
}

namespace {
template <typename T>
const T* by_id(const std::vector<T>& items, const Id& id) {
    for (const T& item : items)
        if (item.id == id) return &item;
    return nullptr;
}
}  // namespace

const Part* Model::part(const Id& id) const { return by_id(parts, id); }
const Section* Model::section(const Id& id) const { return by_id(sections, id); }
const Material* Model::material(const Id& id) const { return by_id(materials, id); }
const Eos* Model::eos(const Id& id) const { return by_id(equations_of_state, id); }
const Box* Model::box(const Id& id) const { return by_id(boxes, id); }

std::string_view to_string(Form f) {
    switch (f) {
        case Form::Default: return "default formulation";
        case Form::Renormalized: return "renormalization";
        case Form::Symmetric: return "symmetric formulation";
        case Form::SymmetricRenormalized: return "symmetric renormalized";
        case Form::Tensor: return "tensor formulation";
        case Form::FluidParticle: return "fluid particle";
        case Form::FluidRenormalized: return "fluid particle with renormalization";
        case Form::TotalLagrangian: return "total Lagrangian";
        case Form::TotalLagrangianRenormalized: return "total Lagrangian with renormalization";
        case Form::Adaptive: return "adaptive SPH (ASPH)";
        case Form::AdaptiveRenormalized: return "renormalized ASPH";
        case Form::MovingLeastSquares: return "moving least squares (MLS)";
        case Form::Incompressible: return "incompressible SPH (ISPH)";
        case Form::EnhancedFluid: return "enhanced fluid";
        case Form::EnhancedFluidRenormalized: return "enhanced fluid with renormalization";
    }
    return "unknown";
}

std::string_view to_string(Dimension d) {
    switch (d) {
        case Dimension::Unset: return "unset";
        case Dimension::PlaneStrain: return "2D plane strain";
        case Dimension::ThreeD: return "3D";
        case Dimension::Axisymmetric: return "2D axisymmetric";
    }
    return "unset";
}

Model::Model() = default;
Model::Model(const Model&) = default;
Model::Model(Model&&) noexcept = default;
Model& Model::operator=(const Model&) = default;
Model& Model::operator=(Model&&) noexcept = default;
Model::~Model() = default;

}  // namespace sphdeck::model
