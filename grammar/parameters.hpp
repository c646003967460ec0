// *PARAMETER definitions in reading order, with their scopes (lsdyna-format.md §14).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "text/source_map.hpp"

namespace sphdeck::grammar {

enum class ParameterType : std::uint8_t { Real, Integer, Character };

struct Parameter {
    std::string name;  // as written (without the type letter)
    ParameterType type = ParameterType::Real;
    double number = 0.0;      // R and I
    std::string text;         // C
    std::uint32_t scope = 0;  // 0 = global; otherwise the FileId + 1 of the file with *PARAMETER_LOCAL
    Span span;                // the name field
};

// *PARAMETER_DUPLICATION DFLAG: what a second definition of a name does.
enum class Duplication : int {
    WarnKeepFirst = 1,  // default
    WarnReplace = 2,
    Error = 3,
    SilentReplace = 4,
    SilentKeepFirst = 5,
};

struct ParameterMatch {
    const Parameter* parameter = nullptr;
    bool case_mismatch = false;  // found only by ignoring case
};

class ParameterTable {
public:
    // Registers that file `file` was opened by `parent` (no_file for a main file), so local
    // scopes can tell ancestors.
    void add_file(FileId file, FileId parent);

    // Appends a definition; returns its index. The caller decides duplication beforehand.
    std::uint32_t define(Parameter p);

    // Number of definitions so far: a block read now sees exactly these.
    std::uint32_t epoch() const { return static_cast<std::uint32_t>(definitions_.size()); }

    // The latest definition of `name` visible from `file` among the first `epoch` ones.
    // Exact-case matches win; otherwise a case-insensitive match is returned and flagged.
    ParameterMatch find(std::string_view name, FileId file, std::uint32_t epoch) const;

    // A definition visible from `file` with the same name (any case), for duplicate checks.
    const Parameter* find_existing(std::string_view name, FileId file) const;

    const std::vector<Parameter>& definitions() const { return definitions_; }

    // The names a block of `file` read at `epoch` can use, each once, for "did you mean".
    std::vector<std::string> visible_names(FileId file, std::uint32_t epoch) const;

    Duplication duplication = Duplication::WarnKeepFirst;

private:
    bool visible(const Parameter& p, FileId file) const;

    std::vector<Parameter> definitions_;
    std::unordered_map<std::string, std::vector<std::uint32_t>> by_upper_name_;
    std::vector<FileId> parent_of_;
};

std::string to_upper(std::string_view s);

}  // namespace sphdeck::grammar
