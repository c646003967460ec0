// RadiossBuilder: dispatch, shared helpers, and the mesh side of a Radioss deck (/BEGIN, /NODE,
// /PART, solid elements, node groups, skews and frames, /ANALY, /DEF_SOLID).
#include <cctype>
#include <cmath>
#include <optional>
#include <fmt/format.h>
#include <type_traits>

#include "grammar/number_cast.hpp"
#include "grammar/value.hpp"
#include "model/radioss_builder.hpp"

namespace sphdeck::model {

RadiossBuilder::RadiossBuilder(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, int version)
    : deck_(deck), out_(out) {
    facts_.version = version;
    model_.controls.sph.memory = Setting<long long>{0};
    model_.controls.sph.idim = Setting<Dimension>{Dimension::ThreeD};
}

void RadiossBuilder::report(const char* code, diag::Severity s, std::string message, grammar::Span span) {
    out_.push_back(diag::Diagnostic{code, s, std::move(message), span, {}});
}

const RadiossValue* RadiossBuilder::value(std::string_view name) const {
    for (const auto& card : cards_)
        for (const RadiossValue& v : card)
            if (v.spec && v.spec->name == name) return &v;
    return nullptr;
}

std::string_view RadiossBuilder::first_named(std::initializer_list<std::string_view> names) const {
    for (std::string_view name : names)
        if (value(name)) return name;
    return *names.begin();
}

template <typename T>
StarterValue<T> RadiossBuilder::starter(std::string_view name, const RadiossBlock& b) const {
    StarterValue<T> s;
    s.span = b.block->span;
    if (const RadiossValue* v = value(name)) {
        s.span = v->span;
        s.explicit_value = v->explicit_value;
        if (v->valid) {
            if constexpr (std::is_integral_v<T>)
                s.written = grammar::saturating_integer<T>(v->number);
            else
                s.written = static_cast<T>(v->number);
        }
    }
    s.value = s.written;
    return s;
}
template StarterValue<double> RadiossBuilder::starter<double>(std::string_view, const RadiossBlock&) const;
template StarterValue<long long> RadiossBuilder::starter<long long>(std::string_view, const RadiossBlock&) const;

StarterValue<std::string> RadiossBuilder::text(std::string_view name, const RadiossBlock& b) const {
    StarterValue<std::string> s;
    s.span = b.block->span;
    if (const RadiossValue* v = value(name)) {
        s.span = v->span;
        s.explicit_value = v->explicit_value;
        s.written = std::string(v->text);
    }
    s.value = s.written;
    return s;
}

// The id in path segment `arg` (the part of /SPHCEL/part_ID, ...); reported when missing or bad.
std::optional<long long> RadiossBuilder::header_id(const RadiossBlock& b, std::size_t arg, std::string_view what) {
    if (arg >= b.args.size()) {
        report("DK008", diag::Severity::Error, fmt::format("{} needs {} in its header", b.spec->name, what),
               b.block->span);
        return std::nullopt;
    }
    grammar::IntegerValue v = grammar::parse_integer(b.args[arg]);
    if (v.status != grammar::NumberStatus::Ok) {
        report("DK002", diag::Severity::Error,
               fmt::format("'{}' in the header of {} is not an integer {}", b.written[arg], b.spec->name, what),
               b.arg_spans[arg]);
        return std::nullopt;
    }
    return v.value;
}

void RadiossBuilder::begin(const RadiossBlock& b) {
    cards_.assign(b.spec->format_for(b.version).cards.size(), {});
    pending_members_.clear();
    pending_tetra10_.clear();
    block_id_.reset();
    const std::string_view name = b.spec->name;
    // Ids of keywords with repeated lines are needed while the lines are read.
    if (name == "/SPHCEL")
        block_id_ = header_id(b, 0, "a part id");
    else if (name == "/BRICK" || name == "/TETRA4" || name == "/TETRA10" || name == "/PENTA6")
        block_id_ = header_id(b, 0, "a part id");
    else if (name == "/NODE" && model_.nodes.id.capacity() < model_.nodes.id.size() + b.block->line_count) {
        const std::size_t n = model_.nodes.id.size() + b.block->line_count;
        model_.nodes.id.reserve(n), model_.nodes.x.reserve(n), model_.nodes.y.reserve(n), model_.nodes.z.reserve(n);
    }
}

void RadiossBuilder::card(const RadiossBlock& b, std::size_t index, std::uint32_t line,
                          const std::vector<RadiossValue>& values) {
    const std::string_view name = b.spec->name;
    if (name == "/NODE") return add_node(values);
    if (name == "/SPHCEL") return add_particle(b, line, values);
    if (name == "/BRICK" || name == "/TETRA4" || name == "/TETRA10" || name == "/PENTA6")
        return add_element(b, index, line, values);
    if (name == "/GRNOD/NODE" || name == "/GRNOD/PART") return add_group_members(values);
    if (name == "/INISPHCEL") return add_initial_state(b, index, line, values);
    const auto& cards = b.spec->format_for(b.version).cards;
    if (cards[index].repeat == grammar::radioss::Repeat::Once) cards_[index] = values;
}

void RadiossBuilder::end(const RadiossBlock& b) {
    // Law-specific tables (/MAT/LAW2...) are handled as their family (/MAT).
    const std::string_view n = b.spec->family.empty() ? b.spec->name : b.spec->family;
    if (n == "/BEGIN")
        end_begin(b);
    else if (n == "/PART")
        end_part(b);
    else if (n == "/FRAME/FIX" || n == "/SKEW/FIX" || n == "/FRAME/MOV" || n == "/SKEW/MOV" || n == "/FRAME" ||
             n == "/SKEW")
        end_frame(b);
    else if (n.rfind("/GRNOD", 0) == 0)
        end_group(b);
    else if (n == "/PROP/SPH")
        end_sph_property(b);
    else if (n == "/PROP/TYPE14")
        end_solid_property(b, 14);
    else if (n == "/PROP/TYPE6")
        end_solid_property(b, 6);
    else if (n == "/PROP")
        end_other_property(b);
    else if (n == "/MAT")
        end_material(b);
    else if (n == "/EOS/POLYNOMIAL")
        end_eos(b);
    else if (n == "/SPHGLO")
        end_sphglo(b);
    else if (n == "/SPHBCS")
        end_sphbcs(b);
    else if (n == "/SPH/INOUT")
        end_inout(b);
    else if (n == "/SPH/RESERVE")
        end_reserve(b);
    else if (n.rfind("/DT", 0) == 0)
        end_dt(b);
    else if (n == "/ANALY") {
        StarterValue<long long> v = starter<long long>("N2D3D", b);
        facts_.analysis = v.value;
        facts_.analysis_span = v.span;
    } else if (n == "/DEF_SOLID") {
        facts_.def_isolid = starter<long long>("Isolid", b).value;
        facts_.def_iframe = starter<long long>("Iframe", b).value;
    }
}

namespace {

// A run name line that ends, after blanks, in a number the starter's versions take (41 to 2026 and a little
// beyond): with Invers blank below it, the version line was joined to the run name (its line end deleted).
// The column to break the line at, so that the version ends at column 10 (the I10 cell), or nothing.
std::optional<std::size_t> version_joined_at(std::string_view line) {
    const std::size_t end = line.find_last_not_of(" \r") + 1;
    if (end == 0) return std::nullopt;
    const std::size_t start = line.find_last_of(' ', end - 1) + 1;  // npos + 1 == 0: one word, no name
    if (start == 0) return std::nullopt;
    const std::size_t name_end = line.find_last_not_of(' ', start - 1) + 1;
    const grammar::IntegerValue v = grammar::parse_integer(line.substr(start, end - start));
    constexpr long long oldest = 41, newest = grammar::radioss::latest_version + 10;
    if (name_end == 0 || start - name_end < 2 || v.status != grammar::NumberStatus::Ok || v.value < oldest ||
        v.value > newest || end - name_end > 10)
        return std::nullopt;
    return std::max(name_end, end >= 10 ? end - 10 : std::size_t{0});
}

}  // namespace

void RadiossBuilder::end_begin(const RadiossBlock& b) {
    facts_.begin_present = true;
    const RadiossValue* name = value("Runname");
    if (name) facts_.run_name = std::string(name->text);
    const RadiossValue* invers = value("Invers");
    if (invers) facts_.version_span = invers->span;
    if (invers && !invers->explicit_value) report_blank_version(b, *invers);
    const char* input[] = {"Input_mass", "Input_length", "Input_time"};
    const char* work[] = {"Work_mass", "Work_length", "Work_time"};
    for (int k = 0; k < 3; ++k) {
        if (const RadiossValue* v = value(input[k]); v && v->explicit_value) facts_.input_units[k] = v->text;
        if (const RadiossValue* v = value(work[k]); v && v->explicit_value) facts_.work_units[k] = v->text;
    }
}

// Invers blank on /BEGIN's version line: the deck's version is not known (sphdeck reads the newest formats). A
// warning: what the starter then reads is not known here. When the run name above ends in a version after its
// blanks, the two lines were one: DK037 on the run name line, with the line end put back (an unsafe fix).
void RadiossBuilder::report_blank_version(const RadiossBlock& b, const RadiossValue& invers) {
    const grammar::CardLinePtr first = deck_.begin_lines(*b.block);
    const std::string_view line = deck_.text(*first);
    if (const std::optional<std::size_t> at = version_joined_at(line)) {
        const auto column = static_cast<std::uint32_t>(*at + 1);
        const std::string_view version = grammar::trim_blanks(line.substr(*at));
        diag::Diagnostic d{
            "DK037",
            diag::Severity::Warning,
            fmt::format("two lines made one: the line end before column {} was deleted, so Invers {} is read as part "
                        "of the run name, and Invers from the line below, blank there: the deck's version is unknown "
                        "(sphdeck reads the newest formats, {})",
                        column, version, grammar::radioss::latest_version),
            grammar::Span{first->file, first->line, column, static_cast<std::uint32_t>(line.size() + 1)},
            {}};
        d.fixes.push_back(
            {fmt::format("break the line before column {}, so that {} is read as Invers", column, version),
             false,
             {{grammar::Span{first->file, first->line, column, column}, "\n"}}});
        out_.push_back(std::move(d));
        return;
    }
    report("DK008", diag::Severity::Warning,
           fmt::format("Invers, the deck's input version, is blank on /BEGIN's second line: the deck's formats are "
                       "unknown (sphdeck reads the newest, {})",
                       grammar::radioss::latest_version),
           invers.span);
}

void RadiossBuilder::add_node(const std::vector<RadiossValue>& v) {
    if (v.size() < 4 || !v[0].valid) return;
    Nodes& n = model_.nodes;
    n.id.push_back(grammar::saturating_integer<long long>(v[0].number));
    n.x.push_back(v[1].number);
    n.y.push_back(v[2].number);
    n.z.push_back(v[3].number);
}

void RadiossBuilder::end_part(const RadiossBlock& b) {
    auto id = header_id(b, 0, "a part id");
    if (!id) return;
    Part p;
    p.id = std::to_string(*id);
    p.heading = b.title;
    p.span = b.arg_spans[0];
    auto ref = [&](std::string_view field) {
        StarterValue<long long> v = starter<long long>(field, b);
        const bool given = v.explicit_value && v.written != 0;
        return Setting<Id>{given ? std::to_string(v.written) : Id{}, given, v.span};
    };
    p.section = ref("prop_ID");
    p.material = ref("mat_ID");
    p.eos = Setting<Id>{Id{}, false, b.block->span};
    model_.parts.push_back(std::move(p));
}

void RadiossBuilder::add_element(const RadiossBlock& b, std::size_t card, std::uint32_t line,
                                 const std::vector<RadiossValue>& v) {
    if (!block_id_) return;
    const std::string_view name = b.spec->name;
    RadiossSolids& s = name == "/BRICK"     ? facts_.bricks
                       : name == "/TETRA4"  ? facts_.tetra4
                       : name == "/TETRA10" ? facts_.tetra10
                                            : facts_.penta6;
    if (name == "/TETRA10") {
        if (card == 0) {  // the id line; its nodes follow on the next line
            pending_tetra10_.assign(1,
                                    v.empty() || !v[0].valid ? 0 : grammar::saturating_integer<long long>(v[0].number));
            pending_tetra10_line_ = line;
            return;
        }
        if (pending_tetra10_.empty()) return;
        s.id.push_back(pending_tetra10_.front());
        s.line.push_back(pending_tetra10_line_);
        pending_tetra10_.clear();
        for (std::size_t k = 0; k < 10; ++k)
            s.nodes.push_back(k < v.size() && v[k].valid ? grammar::saturating_integer<long long>(v[k].number) : 0);
        s.part.push_back(*block_id_);
        return;
    }
    if (v.empty() || !v[0].valid) return;
    s.id.push_back(grammar::saturating_integer<long long>(v[0].number));
    s.part.push_back(*block_id_);
    s.line.push_back(line);
    for (int k = 1; k <= s.nodes_per_element; ++k)
        s.nodes.push_back(static_cast<std::size_t>(k) < v.size() && v[k].valid
                              ? grammar::saturating_integer<long long>(v[k].number)
                              : 0);
}

void RadiossBuilder::add_group_members(const std::vector<RadiossValue>& v) {
    for (const RadiossValue& x : v)
        if (x.valid && x.number != 0) pending_members_.push_back(grammar::saturating_integer<long long>(x.number));
}

void RadiossBuilder::end_group(const RadiossBlock& b) {
    // The id is the last segment: /GRNOD/NODE/5, /GRNOD/BOX/7.
    if (b.args.empty()) return;
    auto id = header_id(b, b.args.size() - 1, "a group id");
    if (!id) return;
    RadiossNodeGroup g;
    g.id = *id;
    g.keyword = b.block->keyword;
    g.span = b.block->span;
    if (b.spec->name == "/GRNOD/NODE") {
        g.resolved = true;
        model_.node_sets.push_back(IdSet{std::to_string(*id), b.block->span, pending_members_});
    } else if (b.spec->name == "/GRNOD/PART") {
        g.resolved = true;
        part_groups_.emplace_back(*id, pending_members_);
    }
    facts_.node_groups.push_back(std::move(g));
}

void RadiossBuilder::end_frame(const RadiossBlock& b) {
    if (b.args.empty()) return;
    // /FRAME/FIX/id (V4: /FRAME/FIX/id/title); the generic /FRAME/<kind>/id: the last segment.
    const bool generic = b.spec->name == "/FRAME" || b.spec->name == "/SKEW";
    auto id = header_id(b, generic ? b.args.size() - 1 : 0, "an id");
    if (!id) return;
    RadiossFrame f;
    f.id = *id;
    f.skew = b.block->keyword.rfind("/SKEW", 0) == 0;
    f.keyword = b.block->keyword;
    f.span = b.block->span;
    const std::string_view name = b.spec->name;
    f.moving = name != "/FRAME/FIX" && name != "/SKEW/FIX";
    if (!f.moving) {
        auto get = [&](std::string_view field) {
            const RadiossValue* v = value(field);
            return v && v->valid ? v->number : 0.0;
        };
        f.origin = {get("Ox"), get("Oy"), get("Oz")};
        std::array<double, 3> y{get("Yx"), get("Yy"), get("Yz")}, z{get("Zx"), get("Zy"), get("Zz")};
        if (f.skew) {
            // hm_read_skw.F: an axis without x and z (y, resp. x and y) components is the global
            // one, so a blank /SKEW/FIX is the global system. hm_read_frm.F has no such default.
            if (y[0] == 0 && y[2] == 0) y[1] = std::signbit(y[1]) ? -1 : 1;
            if (z[0] == 0 && z[1] == 0) z[2] = std::signbit(z[2]) ? -1 : 1;
        }
        f.axes[1] = y, f.axes[2] = z;  // X' = Y' x Z' in resolve_frames
        f.geometry = true;
    } else if (name == "/FRAME/MOV" || name == "/SKEW/MOV") {
        for (int k = 0; k < 3; ++k) {
            const RadiossValue* v = value(fmt::format("node_ID{}", k + 1));
            f.nodes[k] = v && v->valid ? grammar::saturating_integer<long long>(v->number) : 0;
        }
        // hm_read_frm.F / hm_read_skw.F: the last X, Y or Z letter of the Dir cell; X by default.
        if (const RadiossValue* dir = value("Dir"))
            for (char c : dir->text) {
                const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
                if (u >= 'X' && u <= 'Z') f.dir = u - 'X';
            }
    }
    facts_.frames.push_back(std::move(f));
}

}  // namespace sphdeck::model
