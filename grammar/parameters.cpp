#include "grammar/parameters.hpp"

#include <algorithm>
#include <cctype>

namespace sphdeck::grammar {

std::string to_upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

void ParameterTable::add_file(FileId file, FileId parent) {
    if (parent_of_.size() <= file) parent_of_.resize(file + 1, no_file);
    parent_of_[file] = parent;
}

std::uint32_t ParameterTable::define(Parameter p) {
    auto index = static_cast<std::uint32_t>(definitions_.size());
    by_upper_name_[to_upper(p.name)].push_back(index);
    definitions_.push_back(std::move(p));
    return index;
}

// A local parameter is visible in its own file and in the files that file includes.
bool ParameterTable::visible(const Parameter& p, FileId file) const {
    if (p.scope == 0) return true;
    FileId owner = p.scope - 1;
    for (FileId f = file; f != no_file && f < parent_of_.size(); f = parent_of_[f])
        if (f == owner) return true;
    return false;
}

ParameterMatch ParameterTable::find(std::string_view name, FileId file, std::uint32_t epoch) const {
    auto it = by_upper_name_.find(to_upper(name));
    if (it == by_upper_name_.end()) return {};
    ParameterMatch loose;
    for (auto i = it->second.rbegin(); i != it->second.rend(); ++i) {
        if (*i >= epoch) continue;
        const Parameter& p = definitions_[*i];
        if (!visible(p, file)) continue;
        if (p.name == name) return {&p, false};
        if (!loose.parameter) loose = {&p, true};
    }
    return loose;
}

std::vector<std::string> ParameterTable::visible_names(FileId file, std::uint32_t epoch) const {
    std::vector<std::string> out;
    for (std::uint32_t i = 0; i < epoch && i < definitions_.size(); ++i) {
        const Parameter& p = definitions_[i];
        if (visible(p, file) && std::find(out.begin(), out.end(), p.name) == out.end()) out.push_back(p.name);
    }
    return out;
}

const Parameter* ParameterTable::find_existing(std::string_view name, FileId file) const {
    return find(name, file, epoch()).parameter;
}

}  // namespace sphdeck::grammar
