#include "grammar/radioss/cell_names.hpp"

namespace sphdeck::grammar::radioss {

std::string_view cell_kind_name(Cell cell) {
    switch (cell) {
        case Cell::Int: return "integer";
        case Cell::Real: return "real";
        case Cell::Text:
        case Cell::Text20: return "text";
        case Cell::Line: return "line";
        case Cell::Skip:
        case Cell::Skip20: return "unused";
    }
    return "unused";
}

}  // namespace sphdeck::grammar::radioss
