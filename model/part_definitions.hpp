// What a part reads: its section, material and EOS. *CASE blocks may define one id once per case
// (model/case_blocks.hpp); a part reads the first definition of the id that is read in its own run.
#pragma once

#include <vector>

#include "grammar/raw_deck.hpp"
#include "model/case_blocks.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

class PartDefinitions {
public:
    PartDefinitions(const Model& model, const grammar::RawDeck& deck);
    // Null when no definition of the id is read in the part's run.
    const Section* section_of(const Part& part) const;
    const Material* material_of(const Part& part) const;
    const Eos* eos_of(const Part& part) const;
    // "n" for a part inside *CASE_BEGIN_n ... *CASE_END_n, else "" (read in every case).
    std::string_view case_of(const Part& part) const { return cases_.case_of(part.span); }

private:
    template <typename T>
    const T* in_run(const std::vector<T>& items, const Id& id, const Part& part) const;

    const Model& model_;
    CaseBlocks cases_;
};

}  // namespace sphdeck::model
