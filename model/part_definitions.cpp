#include "model/part_definitions.hpp"

namespace sphdeck::model {

PartDefinitions::PartDefinitions(const Model& model, const grammar::RawDeck& deck) : model_(model), cases_(deck) {}

template <typename T>
const T* PartDefinitions::in_run(const std::vector<T>& items, const Id& id, const Part& part) const {
    const std::string_view part_case = cases_.case_of(part.span);
    for (const T& item : items)
        if (item.id == id && same_run(cases_.case_of(item.span), part_case)) return &item;
    return nullptr;
}

// Without case blocks every definition is read in the one run: the model's own look-ups.
const Section* PartDefinitions::section_of(const Part& part) const {
    if (!cases_.any()) return model_.section(part.section.value);
    return in_run(model_.sections, part.section.value, part);
}

const Material* PartDefinitions::material_of(const Part& part) const {
    if (!cases_.any()) return model_.material(part.material.value);
    return in_run(model_.materials, part.material.value, part);
}

const Eos* PartDefinitions::eos_of(const Part& part) const {
    if (!cases_.any()) return model_.eos(part.eos.value);
    return in_run(model_.equations_of_state, part.eos.value, part);
}

}  // namespace sphdeck::model
