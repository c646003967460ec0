// DK012 "undefined parameter": why, when the deck says: a reference cut by its field (the name read
// is the start of a defined, longer name) or a close defined name (did you mean, with an unsafe fix).
#pragma once

#include <string_view>

#include "diag/diagnostic.hpp"
#include "grammar/parameters.hpp"
#include "grammar/value.hpp"

namespace sphdeck::grammar {

struct UndefinedReference {
    std::string_view name;          // as read, without '&'
    Span name_span;                 // the columns of the name (after '&'); invalid when not known
    bool fills_field = false;       // the name ends at the last column of a fixed-width field
    std::uint32_t field_width = 0;  // that field's width (for the message)
};

// The DK012 finding for `ref`, found at `span`, with the names visible from `file` at `epoch`.
diag::Diagnostic undefined_parameter(const ParameterTable& table, const UndefinedReference& ref, Span span, FileId file,
                                     std::uint32_t epoch);

// The reference of a classified field value (`token`) in a field cut from `field_text` at `field_span`:
// where its name sits and whether it fills the field (fixed format only: `fixed_width` > 0).
UndefinedReference reference_in_field(const ValueToken& token, std::string_view field_text, Span field_span,
                                      std::uint32_t fixed_width);

}  // namespace sphdeck::grammar
