#include "mcp/tool.hpp"

#include <cmath>

namespace sphdeck::mcp {
namespace {

using json = nlohmann::json;

// Whether `value` has the JSON Schema type `type` (the types the tools' schemas use).
bool has_type(const json& value, const std::string& type, const json& property) {
    if (type == "string") return value.is_string();
    if (type == "boolean") return value.is_boolean();
    if (type == "number") return value.is_number();
    if (type == "integer")
        return value.is_number_integer() || (value.is_number_float() && std::isfinite(value.get<double>()) &&
                                             std::floor(value.get<double>()) == value.get<double>());
    if (type == "array") {
        if (!value.is_array()) return false;
        const std::string item = property.contains("items") ? property["items"].value("type", "") : "";
        for (const json& v : value)
            if (!item.empty() && !has_type(v, item, property["items"])) return false;
        return true;
    }
    return true;
}

void check_range(const std::string& name, const json& value, const json& property) {
    if (!value.is_number()) return;
    const double v = value.get<double>();
    if (property.contains("minimum") && v < property["minimum"].get<double>())
        throw InvalidParams("argument '" + name + "' must be at least " + property["minimum"].dump());
    if (property.contains("maximum") && v > property["maximum"].get<double>())
        throw InvalidParams("argument '" + name + "' must be at most " + property["maximum"].dump());
}

void check_enum(const std::string& name, const json& value, const json& property) {
    if (!property.contains("enum")) return;
    for (const json& allowed : property["enum"])
        if (allowed == value) return;
    throw InvalidParams("argument '" + name + "' must be one of " + property["enum"].dump());
}

}  // namespace

Arguments::Arguments(const json& arguments, const json& schema) {
    if (arguments.is_null())
        values_ = json::object();
    else if (arguments.is_object())
        values_ = arguments;
    else
        throw InvalidParams("the tool's arguments must be an object");
    const json& properties = schema["properties"];
    for (const auto& [name, value] : values_.items()) {
        if (!properties.contains(name)) {
            std::string known;
            for (const auto& [k, unused] : properties.items()) known += (known.empty() ? "" : ", ") + k;
            throw InvalidParams("unknown argument '" + name + "' (the tool takes: " + known + ")");
        }
        const json& property = properties[name];
        const std::string type = property.value("type", "");
        if (!type.empty() && !has_type(value, type, property))
            throw InvalidParams("argument '" + name + "' must be of type " + type);
        check_range(name, value, property);
        check_enum(name, value, property);
    }
    if (schema.contains("required"))
        for (const json& name : schema["required"])
            if (!values_.contains(name.get<std::string>()))
                throw InvalidParams("missing argument '" + name.get<std::string>() + "'");
}

bool Arguments::has(std::string_view name) const { return values_.contains(std::string(name)); }

std::optional<std::string> Arguments::string(std::string_view name) const {
    if (!has(name)) return std::nullopt;
    return values_[std::string(name)].get<std::string>();
}

bool Arguments::boolean(std::string_view name, bool otherwise) const {
    return has(name) ? values_[std::string(name)].get<bool>() : otherwise;
}

std::optional<double> Arguments::number(std::string_view name) const {
    if (!has(name)) return std::nullopt;
    return values_[std::string(name)].get<double>();
}

std::vector<std::string> Arguments::strings(std::string_view name) const {
    if (!has(name)) return {};
    return values_[std::string(name)].get<std::vector<std::string>>();
}

const std::vector<Tool>& tools() {
    static const std::vector<Tool> table = {check_deck_tool(),   fix_deck_tool(),       format_deck_tool(),
                                            explain_rule_tool(), keyword_layout_tool(), smoothing_preview_tool(),
                                            diff_decks_tool()};
    return table;
}

const Tool* find_tool(std::string_view name) {
    for (const Tool& tool : tools())
        if (tool.name == name) return &tool;
    return nullptr;
}

}  // namespace sphdeck::mcp
