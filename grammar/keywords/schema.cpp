// Field layouts per card format, and the small helpers of the schema types.
#include "grammar/keywords/schema.hpp"

#include <algorithm>
#include <cctype>

namespace sphdeck::keywords {

namespace {

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::toupper(static_cast<unsigned char>(a[i])) !=
            std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    }
    return true;
}

// Width of a field (or of the gap before it) after promotion to a format (lsdyna-format.md §6).
std::uint32_t widened(std::uint32_t width, grammar::CardFormat format) {
    switch (format) {
        case grammar::CardFormat::I10: return std::max<std::uint32_t>(width, 10);
        case grammar::CardFormat::Long: return std::max<std::uint32_t>(width, 20);
        case grammar::CardFormat::Standard: break;
    }
    return width;
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
    std::vector<FieldSlot> slots;
    slots.reserve(card.fields.size());
    std::uint32_t pos = 0;         // 0-based offset in the promoted line
    std::uint32_t std_end = 0;     // 0-based end of the previous field in standard format
    for (const FieldSpec& f : card.fields) {
        const std::uint32_t std_start = f.column > 0 ? f.column - 1u : 0u;
        if (std_start > std_end) pos += widened(std_start - std_end, format);  // a gap: unused columns
        std::uint32_t width = widened(f.width, format);
        const bool trailing_text = f.type == FieldType::Text && f.width >= 70 && std_start + f.width == 80;
        if (format == grammar::CardFormat::Long && trailing_text && pos < kLongLine)
            width = std::max(width, kLongLine - pos);
        slots.push_back({pos, width});
        pos += width;
        std_end = std::max(std_end, std_start + f.width);
    }
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
