#include "model/extract.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <type_traits>

#include "grammar/fields.hpp"
#include "grammar/keywords/id_kinds.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/number_cast.hpp"
#include "grammar/value.hpp"

namespace sphdeck::model {
namespace {

// Whether `number` converts to T without undefined behaviour (integers: finite and in range).
template <typename T>
bool fits(double number) {
    if constexpr (std::is_integral_v<T>) return grammar::fits_integer<T>(number);
    return true;
}

template <typename T>
Setting<T> setting(const KeywordRecord& r, std::string_view name, T fallback) {
    Setting<T> s{fallback, false, r.span};
    if (const FieldRecord* f = r.field(name)) {
        if (f->valid && fits<T>(f->number)) s.value = static_cast<T>(f->number);
        s.explicit_value = f->explicit_value;
        s.span = f->span;
    }
    return s;
}

template <typename E>
Setting<E> enum_setting(const KeywordRecord& r, std::string_view name, E fallback) {
    Setting<long long> n = setting<long long>(r, name, static_cast<long long>(fallback));
    return {static_cast<E>(n.value), n.explicit_value, n.span};
}

// An id as the solver reads it: a number ("0001", or "1.0" which DK004 already flags) becomes
// its integer; a label stays text.
Id id_of(const FieldRecord& f) {
    if (!f.explicit_value) return {};
    grammar::ValueToken t = grammar::classify_value(f.text);
    if (f.valid && (t.shape == grammar::ValueShape::Integer || t.shape == grammar::ValueShape::Real))
        if (const std::optional<long long> n = grammar::checked_integer<long long>(f.number)) return std::to_string(*n);
    return normalise_id(f.text);
}

Setting<Id> id_setting(const KeywordRecord& r, std::string_view name) {
    Setting<Id> s{Id{}, false, r.span};
    if (const FieldRecord* f = r.field(name)) {
        s.value = id_of(*f);
        s.explicit_value = f->explicit_value;
        s.span = f->span;
    }
    return s;
}

bool extract_starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// *MAT_ADD_EROSION, *MAT_ADD_THERMAL_EXPANSION, *MAT_THERMAL_... add properties to a material
// defined elsewhere: they name a MID, they do not define one.
bool is_material_keyword(std::string_view name) {
    return extract_starts_with(name, "*MAT_") && !extract_starts_with(name, "*MAT_ADD_") &&
           !extract_starts_with(name, "*MAT_THERMAL_");
}

void extract_control_sph(const KeywordRecord& r, ControlSph& c) {
    c.present = true;
    c.keyword = r.span;
    c.ncbs = setting<long long>(r, "NCBS", 1);
    c.boxid = setting<long long>(r, "BOXID", 0);
    c.dt = setting<double>(r, "DT", 1.0e20);
    c.idim = enum_setting(r, "IDIM", Dimension::Unset);
    c.memory = setting<long long>(r, "MEMORY", 150);
    c.form = enum_setting(r, "FORM", Form::Default);
    c.start = setting<double>(r, "START", 0.0);
    c.maxv = setting<double>(r, "MAXV", 1.0e15);
    c.cont = setting<long long>(r, "CONT", 0);
    c.deriv = setting<long long>(r, "DERIV", 0);
    c.ini = enum_setting(r, "INI", IniMode::BucketSort);
    c.ishow = setting<long long>(r, "ISHOW", 0);
    c.ierod = enum_setting(r, "IEROD", ErosionMode::StayActive);
    c.icont = setting<long long>(r, "ICONT", 0);
    c.iavis = enum_setting(r, "IAVIS", ArtificialViscosity::Monaghan);
    c.isymp = setting<long long>(r, "ISYMP", 100);
    c.ithk = setting<long long>(r, "ITHK", 0);
    c.istab = setting<long long>(r, "ISTAB", 0);
    c.ql = setting<double>(r, "QL", 0.01);
    c.sphsort = setting<long long>(r, "SPHSORT", 0);
    c.ishift = setting<long long>(r, "ISHIFT", 0);
}

void extract_controls(const KeywordRecord& r, Controls& c) {
    const std::string_view name = r.schema->name;
    if (name == "*CONTROL_SPH") {
        extract_control_sph(r, c.sph);
    } else if (name == "*CONTROL_TERMINATION") {
        c.endtim = setting<double>(r, "ENDTIM", 0.0);
    } else if (name == "*CONTROL_TIMESTEP") {
        c.tssfac = setting<double>(r, "TSSFAC", 0.9);
        c.erode = setting<long long>(r, "ERODE", 0);
    } else if (name == "*CONTROL_SOLUTION") {
        c.soln = setting<long long>(r, "SOLN", 0);
    } else if (name == "*CONTROL_BULK_VISCOSITY") {
        c.bulk_viscosity_present = true;
        c.q1 = setting<double>(r, "Q1", 1.5);
        c.q2 = setting<double>(r, "Q2", 0.06);
    }
}

Section sph_section(const KeywordRecord& r) {
    Section s;
    Setting<Id> id = id_setting(r, "SECID");
    s.id = id.value;
    s.span = id.span;
    s.keyword = r.keyword;
    s.sph = true;
    s.ellipse = r.has_option("ELLIPSE");
    s.interaction = r.has_option("INTERACTION");
    s.cslh = setting<double>(r, "CSLH", 1.2);
    s.hmin = setting<double>(r, "HMIN", 0.2);
    s.hmax = setting<double>(r, "HMAX", 2.0);
    s.sphini = setting<double>(r, "SPHINI", 0.0);
    s.death = setting<double>(r, "DEATH", 1.0e20);
    s.start = setting<double>(r, "START", 0.0);
    s.kernel = enum_setting(r, "SPHKERN", Kernel::CubicSpline);
    return s;
}

void extract_parts(const KeywordRecord& r, std::vector<Part>& parts) {
    // Rows alternate heading card / data card (the repeated group of *PART).
    std::string heading;
    for (const auto& row : r.rows) {
        if (!row.empty() && row.front().name == "HEADING") {
            heading = row.front().text;
            continue;
        }
        KeywordRecord one{r.schema, r.keyword, r.options, r.span, {row}};
        Part p;
        Setting<Id> pid = id_setting(one, "PID");
        p.id = pid.value;
        p.span = pid.span;
        p.heading = heading;
        p.section = id_setting(one, "SECID");
        p.material = id_setting(one, "MID");
        p.eos = id_setting(one, "EOSID");
        p.hourglass = id_setting(one, "HGID");
        p.thermal_material = id_setting(one, "TMID");
        if (p.eos.value == "0") p.eos.value.clear();  // 0 = no EOS
        if (p.hourglass.value == "0") p.hourglass.value.clear();
        parts.push_back(std::move(p));
    }
}

// `limit` bounds what a _GENERATE range expands to: ids past the model's own are missing anyway
// (REF001 says so), and "1 200000000" must not take gigabytes.
// A 0 is an empty slot, not a member: LS-DYNA ids are positive ("NID: node ID", "PID: part ID"
// of *SET_NODE_LIST / *SET_PART_LIST), LS-PrePost and pydyna pad the last line of a list (and
// of a _GENERATE range card) with zeros, and LS-DYNA skips them.
std::vector<long long> set_members(const KeywordRecord& r, std::size_t limit, bool& truncated) {
    std::vector<long long> members;
    const bool generate = r.has_option("GENERATE");
    for (const auto& row : r.rows) {
        // Member rows only: not the title (_TITLE) nor the SID header card.
        if (row.empty() || row.front().name == "TITLE" || row.front().name == "SID") continue;
        if (generate) {  // B1BEG B1END ... pairs of ranges
            for (std::size_t k = 0; k + 1 < row.size(); k += 2) {
                // A bound that is no integer (1e20: DK007 on its field) makes no range.
                const auto first = grammar::checked_integer<long long>(row[k].number);
                const auto last = grammar::checked_integer<long long>(row[k + 1].number);
                if (!row[k].explicit_value || !row[k + 1].explicit_value || !first || !last) continue;
                for (long long id = *first; id <= *last; ++id) {
                    if (id != 0) {
                        if (members.size() >= limit) {
                            truncated = true;
                            return members;
                        }
                        members.push_back(id);
                    }
                    if (id == *last) break;  // no ++ past LLONG_MAX
                }
            }
        } else {
            for (const auto& f : row)
                if (f.explicit_value && f.valid && f.number != 0)
                    if (const auto id = grammar::checked_integer<long long>(f.number)) members.push_back(*id);
        }
    }
    return members;
}

void extract_record(const KeywordRecord& r, std::size_t index, Model& m) {
    const std::string_view name = r.schema->name;
    if (extract_starts_with(name, "*CONTROL_")) return extract_controls(r, m.controls);
    if (name == "*SECTION_SPH") return m.sections.push_back(sph_section(r));
    if (name == "*PART") return extract_parts(r, m.parts);
    if (is_material_keyword(name)) {
        Setting<Id> id = id_setting(r, "MID");
        const FieldRecord* ro = r.field("RO");  // text that is no number is DK003's, not a density of 0
        m.materials.push_back({id.value, std::string(name), id.span, setting<double>(r, "RO", 0.0), index,
                               ro && (ro->valid || !ro->explicit_value)});
        return;
    }
    if (extract_starts_with(name, "*EOS_")) {
        Setting<Id> id = id_setting(r, "EOSID");
        m.equations_of_state.push_back({id.value, std::string(name), id.span, index});
        return;
    }
    if (name == "*DEFINE_BOX" || name == "*DEFINE_BOX_SPH") {
        Setting<Id> id = id_setting(r, "BOXID");
        Box b{id.value, id.span, {}};
        const char* fields[] = {"XMN", "XMX", "YMN", "YMX", "ZMN", "ZMX"};
        for (int i = 0; i < 6; ++i) b.bounds[i] = setting<double>(r, fields[i], 0.0).value;
        m.boxes.push_back(b);
        return;
    }
    if (name == "*BOUNDARY_SPH_SYMMETRY_PLANE") {
        for (const auto& row : r.rows) {
            KeywordRecord one{r.schema, r.keyword, r.options, r.span, {row}};
            SymmetryPlane p;
            const char* tail[] = {"VTX", "VTY", "VTZ"};
            const char* head[] = {"VHX", "VHY", "VHZ"};
            for (int i = 0; i < 3; ++i) {
                p.tail[i] = setting<double>(one, tail[i], 0.0).value;
                p.head[i] = setting<double>(one, head[i], 0.0).value;
            }
            p.span = row.empty() ? r.span : grammar::Span{row.front().span.file, row.front().span.line, 1, 61};
            m.symmetry_planes.push_back(p);
        }
        return;
    }
    if (name == "*SET_NODE_LIST" || name == "*SET_PART_LIST") {
        Setting<Id> id = id_setting(r, "SID");
        const std::size_t model_size = name == "*SET_NODE_LIST" ? m.nodes.id.size() : m.parts.size();
        IdSet s{id.value, id.span, {}, false};
        s.members = set_members(r, model_size + 1000, s.truncated);
        (name == "*SET_NODE_LIST" ? m.node_sets : m.part_sets).push_back(std::move(s));
    }
}

// The first id of a block the schema does not know (*SECTION_SHELL, *MAT_RIGID, *EOS_JWL...):
// LS-DYNA puts it in columns 1-10 of the first data card, after the title line of _TITLE.
bool raw_first_id(const grammar::RawDeck& deck, const grammar::Block& block, Id& id, grammar::Span& span) {
    grammar::CardLinePtr line = deck.begin_lines(block);
    line += keywords::title_lines(block.keyword);
    if (line >= deck.end_lines(block)) return false;
    std::string_view text = deck.text(*line);
    std::size_t width = block.format == grammar::CardFormat::Long ? 20 : 10;
    std::string_view field = text.substr(0, std::min(text.size(), width));
    if (grammar::is_free_format(text)) field = text.substr(0, text.find(','));
    id = normalise_id(field);
    span = grammar::Span{line->file, line->line, 1, static_cast<std::uint32_t>(field.size() + 1)};
    return !id.empty();
}

// A field of a generated-layout block read straight from its first data line (after the title
// line of _TITLE): the first card of the keyword's layout that has `id_field`, the slot of `name` on it
// in the block's format (or the name-th comma field of a free-format line). Nothing when the tables do
// not know the keyword or the card has no such field.
struct RawField {
    std::string_view text;
    grammar::Span span;
    grammar::CardLinePtr line = nullptr;
};
std::optional<RawField> raw_field(const grammar::RawDeck& deck, const grammar::Block& b, std::string_view id_field,
                                  std::string_view name) {
    grammar::CardLinePtr line = deck.begin_lines(b) + keywords::title_lines(b.keyword);
    if (line >= deck.end_lines(b)) return std::nullopt;
    const std::optional<keywords::KeywordMatch> known = keywords::find_keyword(b.keyword);
    if (!known) return std::nullopt;
    // Generated layouts list the title card (of _TITLE) first: the card with the id is the data card.
    const auto& cards = known->schema->cards;
    auto card =
        std::find_if(cards.begin(), cards.end(), [&](const keywords::CardSpec& c) { return c.field(id_field); });
    if (card == cards.end()) return std::nullopt;
    std::size_t k = 0;
    while (k < card->fields.size() && card->fields[k].name != name) ++k;
    if (k == card->fields.size()) return std::nullopt;
    const std::string_view text = deck.text(*line);
    std::uint32_t start = 0, width = 0;
    if (grammar::is_free_format(text)) {
        std::size_t from = 0;
        for (std::size_t n = 0; n < k && from != std::string_view::npos; ++n) {
            from = text.find(',', from);
            if (from != std::string_view::npos) ++from;
        }
        if (from == std::string_view::npos) from = text.size();
        const std::size_t end = std::min(text.find(',', from), text.size());
        start = static_cast<std::uint32_t>(from), width = static_cast<std::uint32_t>(end - from);
    } else {
        const std::vector<keywords::FieldSlot> slots = keywords::layout(*card, b.format);
        if (k < slots.size()) start = slots[k].start, width = slots[k].width;
    }
    RawField f;
    f.text = start < text.size() ? text.substr(start, width) : std::string_view{};
    f.span = grammar::Span{line->file, line->line, start + 1, start + std::max<std::uint32_t>(width, 1) + 1};
    f.line = line;
    return f;
}

// *SECTION_SHELL ELFORM as written, 0 when absent or not a plain integer.
long long raw_shell_form(const grammar::RawDeck& deck, const grammar::Block& b) {
    const std::optional<RawField> f = raw_field(deck, b, "SECID", "ELFORM");
    if (!f) return 0;
    const grammar::IntegerValue n = grammar::parse_integer(f->text);
    return n.status == grammar::NumberStatus::Ok ? n.value : 0;
}

// RO of a material read from its generated layout: the field named RO on the first data card (MID,
// RO, ...), in the block's format. Keywords the tables do not know: RO in columns 11-20 (most
// materials), enough for mass and sound-speed checks but not for SPH119 (has_density stays false).
Material raw_material(const grammar::RawDeck& deck, const grammar::Block& b, const Id& id, grammar::Span span) {
    Material mat{id, b.keyword, span, {}, std::nullopt, false};
    grammar::CardLinePtr line = deck.begin_lines(b) + keywords::title_lines(b.keyword);
    if (line >= deck.end_lines(b)) return mat;
    const std::optional<keywords::KeywordMatch> known = keywords::find_keyword(b.keyword);
    if (!known || known->schema->cards.empty()) {
        const std::string_view text = deck.text(*line);
        grammar::RealValue ro = grammar::parse_real(text.size() > 10 ? text.substr(10, 10) : "");
        if (ro.status == grammar::NumberStatus::Ok) mat.density = {ro.value, true, span};
        return mat;
    }
    const std::optional<RawField> field = raw_field(deck, b, "MID", "RO");
    if (!field) return mat;  // a spring, a seatbelt: no density on this layout
    mat.has_density = true;
    mat.density.span = field->span;
    const grammar::ValueToken token = grammar::classify_value(field->text);
    if (token.shape == grammar::ValueShape::Parameter) {  // &rho: its value, when defined (else DK012)
        const grammar::ParameterMatch found = deck.parameters.find(token.name, field->line->file, b.parameter_epoch);
        if (!found.parameter || found.parameter->type == grammar::ParameterType::Character) {
            mat.has_density = false;
            return mat;
        }
        mat.density = {token.negated ? -found.parameter->number : found.parameter->number, true, mat.density.span};
        return mat;
    }
    const grammar::RealValue ro = grammar::to_real(token);
    if (ro.status == grammar::NumberStatus::Ok)
        mat.density = {ro.value, true, mat.density.span};
    else if (token.shape != grammar::ValueShape::Blank)
        mat.has_density = false;  // DK003 says what is wrong
    return mat;
}

// *PART_CONTACT, *PART_INERTIA and other variants the schema lacks: their first two cards are
// *PART's heading and data card (PID SECID MID EOSID HGID), then cards of their own follow. We read
// the first part of the block; variants with several parts per block are rare.
void extract_part_variant(const grammar::RawDeck& deck, const grammar::Block& b, Model& m) {
    grammar::CardLinePtr first = deck.begin_lines(b);
    if (deck.end_lines(b) - first < 2) return;
    const grammar::CardLine& data = first[1];
    std::string_view text = deck.text(data);
    const std::size_t width = b.format == grammar::CardFormat::Long ? 20 : 10;
    auto field = [&](std::size_t k, Setting<Id>& out) {
        std::string_view f = text.size() > k * width ? text.substr(k * width, width) : std::string_view{};
        out.value = normalise_id(f);
        out.explicit_value = !out.value.empty();
        out.span = grammar::Span{data.file, data.line, static_cast<std::uint32_t>(k * width + 1),
                                 static_cast<std::uint32_t>((k + 1) * width + 1)};
    };
    Part p;
    Setting<Id> pid;
    field(0, pid);
    if (pid.value.empty() || grammar::is_free_format(text)) return;
    p.id = pid.value;
    p.span = pid.span;
    p.heading = std::string(deck.text(first[0]));
    p.inertia = extract_starts_with(b.keyword, "*PART_INERTIA");
    field(1, p.section);
    field(2, p.material);
    field(3, p.eos);
    field(4, p.hourglass);
    if (p.eos.value == "0") p.eos.value.clear();
    if (p.hourglass.value == "0") p.hourglass.value.clear();
    m.parts.push_back(std::move(p));
}

void extract_unknown_definitions(const grammar::RawDeck& deck, Model& m) {
    for (const grammar::Block& b : deck.blocks) {
        if (extract_starts_with(b.keyword, "*CONTROL_MPP")) m.controls.mpp_keywords.push_back(b.span);
        const bool section =
            extract_starts_with(b.keyword, "*SECTION_") && !extract_starts_with(b.keyword, "*SECTION_SPH");
        const bool material = is_material_keyword(b.keyword);
        // Only the *PART_ keywords that define parts (grammar/keywords/id_kinds.hpp): *PART_SENSOR names them.
        const bool part_variant = extract_starts_with(b.keyword, "*PART_") && keywords::defines_kind(b.keyword, "PART");
        const bool eos = extract_starts_with(b.keyword, "*EOS_");
        if (!section && !material && !eos && !part_variant) continue;
        if (auto known = keywords::find_keyword(b.keyword);
            known && known->unknown_options.empty() && !known->schema->generated)
            continue;  // known by hand: already extracted from its record
        if (part_variant) {
            extract_part_variant(deck, b, m);
            continue;
        }
        Id id;
        grammar::Span span;
        if (!raw_first_id(deck, b, id, span)) continue;
        if (section) {
            Section s;
            s.id = id;
            s.keyword = b.keyword;
            s.span = span;
            if (extract_starts_with(b.keyword, "*SECTION_SHELL")) s.shell_form = raw_shell_form(deck, b);
            m.sections.push_back(std::move(s));
        } else if (material) {
            m.materials.push_back(raw_material(deck, b, id, span));
        } else {
            m.equations_of_state.push_back({id, b.keyword, span, std::nullopt});
        }
    }
}

}  // namespace

void extract_typed(const grammar::RawDeck& deck, Model& model, std::vector<diag::Diagnostic>& out) {
    for (std::size_t i = 0; i < model.records.size(); ++i) extract_record(model.records[i], i, model);
    extract_unknown_definitions(deck, model);
    const ControlSph& sph = model.controls.sph;
    if (sph.present && sph.idim.value == Dimension::Unset) {
        // No default is documented for IDIM (lsdyna-sph-cards.md §1): say so, do not guess.
        out.push_back({"DK008",
                       diag::Severity::Warning,
                       "IDIM is blank or 0 and has no documented default; write 3, 2 or -2",
                       sph.idim.span,
                       {}});
    }
}

}  // namespace sphdeck::model
