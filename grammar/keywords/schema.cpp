// Field layouts per card format, and the small helpers of the schema types.
#include "grammar/keywords/schema.hpp"

#include <algorithm>
#include <cctype>

namespace sphdeck::keywords {

namespace {

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    }
    return true;
}

constexpr std::uint32_t kLongLine = 160;

}  // namespace

std::string_view to_string(FieldType t) {
    switch (t) {
        case FieldType::Integer: return "I";
        case FieldType::Real: return "F";
        case FieldType::Text: return "A";
        case FieldType::Label: return "I/A";
        case FieldType::Unused: return "-";
    }
    return "?";
}

std::string_view to_string(CardRepeat r) {
    switch (r) {
        case CardRepeat::Once: return "once";
        case CardRepeat::Optional: return "optional";
        case CardRepeat::Repeated: return "repeated";
    }
    return "?";
}

std::string_view to_string(Compare c) {
    switch (c) {
        case Compare::Less: return "<";
        case Compare::LessEqual: return "<=";
        case Compare::Equal: return "==";
        case Compare::NotEqual: return "!=";
        case Compare::GreaterEqual: return ">=";
        case Compare::Greater: return ">";
    }
    return "?";
}

bool CardCondition::holds(double v) const {
    if (!any_of.empty()) return std::find(any_of.begin(), any_of.end(), v) != any_of.end();
    switch (compare) {
        case Compare::Less: return v < value;
        case Compare::LessEqual: return v <= value;
        case Compare::Equal: return v == value;
        case Compare::NotEqual: return v != value;
        case Compare::GreaterEqual: return v >= value;
        case Compare::Greater: return v > value;
    }
    return false;
}

bool is_title_field(std::string_view field_name) {
    return iequals(field_name, "TITLE") || iequals(field_name, "HEADING");
}

std::size_t title_lines(std::string_view keyword) { return keyword.find("_TITLE") != std::string_view::npos ? 1 : 0; }

bool FieldSpec::is_named(std::string_view n) const {
    if (iequals(name, n)) return true;
    return std::any_of(aliases.begin(), aliases.end(), [&](std::string_view a) { return iequals(a, n); });
}

const EnumChoice* FieldSpec::choice(long long v) const {
    for (const EnumChoice& c : choices)
        if (c.value == v) return &c;
    return nullptr;
}

const FieldSpec* CardSpec::field(std::string_view n) const {
    for (const FieldSpec& f : fields)
        if (f.type != FieldType::Unused && f.is_named(n)) return &f;
    return nullptr;
}

bool OptionSpec::is_named(std::string_view s) const {
    if (iequals(suffix, s)) return true;
    return std::any_of(aliases.begin(), aliases.end(), [&](std::string_view a) { return iequals(a, s); });
}

const OptionSpec* KeywordSchema::option(std::string_view s) const {
    for (const OptionSpec& o : options)
        if (o.is_named(s)) return &o;
    return nullptr;
}

bool KeywordMatch::has(std::string_view s) const {
    return std::any_of(options.begin(), options.end(), [&](const OptionSpec* o) { return o->is_named(s); });
}

std::vector<FieldSlot> layout(const CardSpec& card, grammar::CardFormat format) {
    std::vector<grammar::FixedField> standard;
    standard.reserve(card.fields.size());
    for (const FieldSpec& f : card.fields) standard.push_back({f.column > 0 ? f.column - 1u : 0u, f.width});
    std::vector<FieldSlot> slots;
    grammar::widen(standard, format, slots);
    // In long format a trailing A80 name, path or expression field may run to column 160.
    if (format == grammar::CardFormat::Long && !card.fields.empty()) {
        const FieldSpec& last = card.fields.back();
        if (last.type == FieldType::Text && last.width >= 70 && last.column - 1u + last.width == 80 &&
            slots.back().start < kLongLine)
            slots.back().width = std::max(slots.back().width, kLongLine - slots.back().start);
    }
    return slots;
}

std::vector<FieldSlot> layout_to_write(std::string_view keyword, const CardSpec& card, grammar::CardFormat format) {
    std::vector<FieldSlot> slots = layout(card, format);
    if (keyword != "*ELEMENT_SPH" || format != grammar::CardFormat::Standard) return slots;
    for (std::size_t i = 0; i < card.fields.size() && i < slots.size(); ++i)
        if (card.fields[i].name == "NEND" && slots[i].width == 10) slots[i].width = 8;
    return slots;
}

std::uint32_t significant_width(const CardSpec& card, grammar::CardFormat format) {
    const std::uint32_t base = card.line_width;
    if (format == grammar::CardFormat::Standard) return base;
    std::uint32_t end = 0;
    for (const FieldSlot& s : layout(card, format)) end = std::max(end, s.start + s.width);
    const std::uint32_t floor = format == grammar::CardFormat::Long ? std::max(base, kLongLine) : base;
    return std::max(floor, end);
}

}  // namespace sphdeck::keywords
