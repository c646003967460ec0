// REF001-REF009: references between definitions (particle → node, part → section, material,
// EOS; sets; boxes), duplicate ids and unused definitions.
#include <algorithm>
#include <charconv>
#include <vector>
#include <fmt/format.h>
#include <tuple>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include "lint/letter_o_ids.hpp"
#include "lint/particle_groups.hpp"
#include "lint/rules.hpp"
#include "lint/rules_references_links.hpp"
#include "lint/rules_thermal_duplicates.hpp"
#include "model/case_blocks.hpp"
#include "model/id_index.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::lint {
namespace {

// The keywords that define what a reference names, in the deck's own language.
struct DefiningWords {
    const char* node;
    const char* section;
    const char* material;
    const char* eos;
    const char* section_field;  // the /PART or *PART field naming them
    const char* material_field;
    const char* part;
};
DefiningWords words(const RuleContext& c) {
    if (c.model.radioss) return {"/NODE", "/PROP", "/MAT", "/EOS", "prop_ID", "mat_ID", "/PART"};
    return {"*NODE", "*SECTION_", "*MAT_", "*EOS_", "SECID", "MID", "*PART"};
}

using model::Id;

std::string listed_reference_ids(const std::vector<long long>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size() && i < max_listed; ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
    if (ids.size() > max_listed) s += ", ...";
    return s;
}

// A pattern that explains why particles name parts no *PART defines, or "".
std::string undefined_part_hint(const RuleContext& c, const PartGroups& missing, bool part_is_node) {
    std::size_t particles = 0;
    for (const auto& [id, g] : missing.by_part) particles += g.count;
    if (part_is_node && particles > 2) return "the part id equals the node id on every line: columns swapped?";
    if (c.model.parts.empty())
        return fmt::format("the deck defines no {}: a mesh without its parts (a missing include?)", words(c).part);
    return "";
}

// REF002 for particles: once per undefined part with its particle count; when more than a few parts
// are undefined (a mesh fragment without its parts, a PID column holding something else), one
// finding for them all with the first lines, instead of one per part (a finding per particle when
// every particle names its own part).
void report_undefined_parts(RuleContext& c, const PartGroups& missing, bool part_is_node) {
    if (missing.by_part.empty()) return;
    const model::Particles& p = c.model.particles;
    const std::string hint = undefined_part_hint(c, missing, part_is_node);
    if (!missing.flood()) {
        for (const auto& [id, g] : missing.by_part) {
            std::string count = g.count > 1 ? fmt::format(" ({} particles)", g.count) : "";
            // A *PART whose PID holds the letter O for a 0 ("1O" for 10): the mistake is there.
            if (const model::Part* typed = letter_o_definition(c.model.parts, std::to_string(id))) {
                auto& d = c.report("REF002", typed->span,
                                   fmt::format("part id {} holds the letter O for the digit 0: LS-DYNA reads the label "
                                               "{}, so particle part {} is not defined{}",
                                               typed->id, typed->id, id, count));
                d.notes.push_back({c.particle_span(g.first.front()),
                                   fmt::format("particle {} names part {} here", p.node[g.first.front()], id)});
                if (auto fix = letter_o_fix(letter_o_digits(typed->id), typed->span)) d.fixes.push_back(*fix);
                continue;
            }
            auto& d = c.report("REF002", c.particle_span(g.first.front()),
                               fmt::format("particle part {} is not defined{}", id, count));
            if (!hint.empty() && id == missing.by_part.begin()->first) d.notes.push_back({{}, hint});
        }
        return;
    }
    const ParticleGroup all = missing.merged();
    auto& d = c.report("REF002", c.particle_span(all.first.front()),
                       fmt::format("{} particles name {} parts that are not defined: parts {}; particles {}", all.count,
                                   missing.by_part.size(), missing.part_list(), all.ids(p)));
    add_line_notes(c, d, all,
                   [&](std::size_t i) { return fmt::format("particle {} names part {}", p.node[i], p.part[i]); });
    if (!hint.empty()) d.notes.push_back({{}, hint});
}

// REF001 and REF002 for particles: grouped per missing id, so a million bad particles make a
// handful of findings, each at the first particle that names it.
// What any_missing needs of the particles alone (lint/bulk_facts.hpp: one pass, shared by the decks
// of a run over one mesh): whether one names a node that does not exist, and the parts they name
// (a part id that could not be read, below 0, is DK002's). One pass on every thread; each thread
// takes a part once per run of equal ids.
struct ParticleNodesAndParts {
    bool node_missing = false;
    std::vector<long long> parts;  // sorted, each once
};

ParticleNodesAndParts particle_nodes_and_parts(const RuleContext& c, const model::IdIndex& nodes) {
    const model::Particles& p = c.model.particles;
    const std::size_t n = p.size();
    ParticleNodesAndParts out;
    bool missing = false;
    std::vector<long long> parts;
#pragma omp parallel reduction(|| : missing) if (n > 65536)
    {
        std::vector<long long> named;  // this thread's parts
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
            if (!missing && !nodes.find(p.node[i])) missing = true;
            if (p.part[i] >= 0 && (i == 0 || p.part[i] != p.part[i - 1])) named.push_back(p.part[i]);
        }
#pragma omp critical(sphdeck_particle_parts_named)
        parts.insert(parts.end(), named.begin(), named.end());
    }
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    out.node_missing = missing;
    out.parts = std::move(parts);
    return out;
}

// Whether some particle names a missing node or an undefined part.
bool any_missing(const RuleContext& c, const model::IdIndex& nodes) {
    const auto facts = c.bulk_facts().get<ParticleNodesAndParts>([&] { return particle_nodes_and_parts(c, nodes); });
    if (facts->node_missing) return true;
    for (long long part : facts->parts)
        if (!c.model.part(std::to_string(part))) return true;
    return false;
}

void check_particles(RuleContext& c, const model::IdIndex& nodes) {
    const model::Particles& p = c.model.particles;
    // The usual deck names only nodes and parts that exist: the grouping below runs in particle
    // order, on one thread, only when something is missing.
    if (!any_missing(c, nodes)) return;
    std::map<long long, std::pair<std::size_t, std::size_t>> missing_node;  // id → first particle, count
    PartGroups missing_part;
    bool part_is_node = true;  // on every particle whose part is undefined
    std::unordered_map<long long, bool> part_known;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!nodes.find(p.node[i])) {
            auto [it, fresh] = missing_node.try_emplace(p.node[i], i, 0);
            ++it->second.second;
        }
        if (p.part[i] < 0) continue;  // the PID could not be read: DK002 says so
        auto known = part_known.find(p.part[i]);
        if (known == part_known.end())
            known = part_known.emplace(p.part[i], c.model.part(std::to_string(p.part[i])) != nullptr).first;
        if (!known->second) {
            missing_part.add(p.part[i], i);
            part_is_node = part_is_node && p.part[i] == p.node[i];
        }
    }
    // Every particle has its own node: a forgotten node include would make a finding per particle.
    std::size_t shown = 0, more = 0;
    for (const auto& [id, first] : missing_node) {
        if (shown == max_listed) {
            ++more;
            continue;
        }
        ++shown;
        c.report("REF001", c.particle_span(first.first),
                 fmt::format("particle {} has no {} {}", id, words(c).node, id));
    }
    if (more > 0)
        c.report("REF001", c.particle_span(std::next(missing_node.begin(), max_listed)->second.first),
                 fmt::format("{} more particles have no {} (first: {})", more, words(c).node,
                             std::next(missing_node.begin(), max_listed)->first));
    report_undefined_parts(c, missing_part, part_is_node);
}

// Definitions in different *CASE_BEGIN_n blocks are read in different runs (model/case_blocks.hpp).
template <typename T>
void check_duplicates(RuleContext& c, const model::CaseBlocks& cases, const std::vector<T>& items,
                      std::string_view what) {
    std::map<Id, std::vector<const T*>> seen;
    for (const T& item : items) {
        if (item.id.empty()) continue;
        auto& earlier = seen[item.id];
        const std::string_view in_case = cases.case_of(item.span);
        for (const T* first : earlier) {
            if (!model::same_run(cases.case_of(first->span), in_case)) continue;
            c.report("REF006", item.span, fmt::format("{} {} is defined twice", what, item.id))
                .notes.push_back({first->span, "first defined here"});
            break;
        }
        earlier.push_back(&item);
    }
}

// Duplicated node and particle ids: a handful of findings say enough (the rest are usually the
// same mistake, e.g. an include read twice).
constexpr std::size_t max_duplicate_reports = 20;

void check_node_duplicates(RuleContext& c, const model::IdIndex& index) {
    std::set<long long> ids;
    for (const auto& [first, again] : index.duplicates()) {
        if (ids.size() == max_duplicate_reports) break;
        ids.insert(c.model.nodes.id[again]);
    }
    // The lines come from the deck's own node blocks: *NODE, or /NODE in a Radioss deck.
    const auto lines = c.model.radioss ? model::radioss_node_lines(c.deck, ids) : c.node_lines(ids);
    for (const auto& [id, spans] : lines) {
        for (std::size_t k = 1; k < spans.size(); ++k)
            c.report("REF006", spans[k], fmt::format("node {} is defined twice", id))
                .notes.push_back({spans.front(), "first defined here"});
    }
}

void check_particle_duplicates(RuleContext& c) {
    const auto& ids = c.model.particles.node;
    struct ParticleDuplicates {  // a fact of the particles alone (lint/bulk_facts.hpp)
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
    };
    const auto duplicates =
        c.bulk_facts().get<ParticleDuplicates>([&] { return ParticleDuplicates{model::find_duplicate_ids(ids)}; });
    std::size_t reported = 0;
    for (const auto& [first, again] : duplicates->pairs) {
        if (reported++ == max_duplicate_reports) break;
        c.report("REF006", c.particle_span(again), fmt::format("particle {} is defined twice", ids[again]))
            .notes.push_back({c.particle_span(first), "first defined here"});
    }
}

// A thermal-only LS-DYNA analysis (*CONTROL_SOLUTION SOLN 1) solves heat transfer alone: a part's
// properties come from its thermal material TMID (*PART: "thermal properties must be specified for
// all solid, shell and thick shell parts if a thermal ... analysis is being performed"); the
// structural MID is not used, and thermal decks leave it 0.
bool needs_no_structural_material(const RuleContext& c, const model::Part& part) {
    const auto& t = part.thermal_material;
    return !c.model.radioss && c.model.controls.soln.value == 1 && t.explicit_value && !t.value.empty() &&
           t.value != "0";
}

// SECID and MID are ids, and LS-DYNA ids are positive: a 0 written there names no section or
// material 0, it leaves the part without one (pydyna and LS-PrePost write 0 for "not set").
std::string missing_reference(const model::Part& part, std::string_view field, std::string_view what, const Id& id,
                              std::string_view keyword) {
    if (id == "0") return fmt::format("part {} has no {} ({} 0)", part.id, what, field);
    return fmt::format("part {} names {} {}, which no {} defines", part.id, what, id, keyword);
}

// An id defined only in other *CASE blocks than the part's: the part's run reads no definition of it.
std::string missing_in_case(const RuleContext& c, const model::Part& part, std::string_view what, const Id& id) {
    return fmt::format("part {} (in *CASE_BEGIN_{}) names {} {}, which is defined only in other cases", part.id,
                       c.definitions().case_of(part), what, id);
}

// One cause, one finding (issue 26, item 3): the parts that name one missing id are reported once,
// at the first of them in the files' order, with their count and the next places as notes.
struct Naming {
    const model::Part* part;
    grammar::Span place;
    std::string message;                                   // as the finding would read at this part
    std::optional<diag::Fix> fix;                          // at this part
    std::optional<grammar::Span> named_at = std::nullopt;  // the part's field, when `place` is a definition's
};

class MissingIds {
public:
    // `field` keeps apart the ids of one code that name different things (MID 5 and TMID 5); `severity`, when
    // given, is the finding's instead of the rule's.
    Naming& add(std::string_view code, const Id& id, const model::Part& part, grammar::Span place, std::string message,
                std::string_view field = {}, std::optional<diag::Severity> severity = std::nullopt,
                std::string note = {}, std::optional<diag::Fix> fix = std::nullopt) {
        auto [it, fresh] = index_.try_emplace({std::string(code) + "/" + std::string(field), id}, missing_.size());
        if (fresh) missing_.push_back({std::string(code), id, {}, severity, std::move(note)});
        return missing_[it->second].namings.emplace_back(Naming{&part, place, std::move(message), std::move(fix)});
    }

    // The finding placed at a definition whose id holds the letter O (`definition`), the part's field a note.
    void add_at_definition(std::string_view code, const Id& id, const model::Part& part, grammar::Span named_at,
                           grammar::Span definition, std::string message, std::optional<diag::Fix> fix) {
        add(code, id, part, definition, std::move(message), {}, std::nullopt, {}, std::move(fix)).named_at = named_at;
    }

    void report(RuleContext& c) {
        constexpr std::size_t listed_notes = 3, listed_ids = 5;  // the count says the rest
        for (Missing& m : missing_) {
            // The model may hold *PART_ variants apart from *PART: order by place.
            std::stable_sort(m.namings.begin(), m.namings.end(), [](const Naming& a, const Naming& b) {
                return std::tie(a.place.file, a.place.line, a.place.column) <
                       std::tie(b.place.file, b.place.line, b.place.column);
            });
            const std::vector<Naming>& n = m.namings;
            std::string message = n.front().message;
            if (n.size() > 1) {
                std::string ids;
                for (std::size_t k = 0; k < n.size() && k < listed_ids; ++k) ids += (k ? ", " : "") + n[k].part->id;
                message += fmt::format("; {} parts {} ({}{})", n.size(), m.id == "0" ? "have none" : "name it", ids,
                                       n.size() > listed_ids ? ", ..." : "");
            }
            diag::Diagnostic& d = m.severity ? c.report(m.code, *m.severity, n.front().place, std::move(message))
                                             : c.report(m.code, n.front().place, std::move(message));
            if (!m.note.empty()) d.notes.push_back({{}, m.note});
            if (n.front().fix) d.fixes.push_back(*n.front().fix);
            if (n.front().named_at)
                d.notes.push_back({*n.front().named_at, fmt::format("part {} names it here", n.front().part->id)});
            for (std::size_t k = 1; k < n.size() && k <= listed_notes; ++k)
                d.notes.push_back(
                    {n[k].named_at.value_or(n[k].place),
                     fmt::format("part {} {} too", n[k].part->id, m.id == "0" ? "has none" : "names it")});
        }
    }

private:
    struct Missing {
        std::string code;
        Id id;
        std::vector<Naming> namings;
        std::optional<diag::Severity> severity;
        std::string note;  // one, after the message
    };
    std::vector<Missing> missing_;
    std::map<std::pair<std::string, Id>, std::size_t> index_;
};

// TMID names a *MAT_THERMAL_ material. A thermal or coupled analysis (*CONTROL_SOLUTION SOLN 1 or 2) needs it
// ("thermal properties must be specified for all solid, shell and thick shell parts if a thermal or coupled
// structural thermal analysis is being performed", *PART): an error there. A structural analysis does not read
// it, so the manual gives no failure: a warning, since a TMID that names nothing was meant to be 0 (the letter
// O typed for the digit reads as a label).
void check_thermal_material(const RuleContext& c, const model::Part& part, const ThermalMaterialIds& thermal,
                            MissingIds& missing) {
    const auto& t = part.thermal_material;
    if (c.model.radioss || !t.explicit_value || t.value.empty() || t.value == "0" || thermal.unreadable ||
        thermal.ids.count(t.value))
        return;
    const long long soln = c.model.controls.soln.value;
    const bool thermal_run = soln == 1 || soln == 2;
    // The letter O typed for the digit 0 ("O", "1O"): the digits it was meant to be, as an unsafe fix.
    const std::optional<std::string> digits = letter_o_digits(t.value);
    std::optional<diag::Fix> fix = letter_o_fix(digits, t.span);
    missing.add("REF004", t.value, part, t.span,
                fmt::format("part {} names thermal material {} (TMID), which no *MAT_THERMAL_ defines{}", part.id,
                            t.value, letter_o_words(digits)),
                "TMID", thermal_run ? diag::Severity::Error : diag::Severity::Warning,
                thermal_run ? fmt::format("a thermal or coupled analysis (*CONTROL_SOLUTION SOLN {}) reads every "
                                          "part's thermal material",
                                          soln)
                            : "a structural analysis (SOLN 0) does not read TMID, but the value names nothing",
                std::move(fix));
}

// HGID names a *HOURGLASS (0 or blank: the defaults). A number no *HOURGLASS line gives, or a label when every
// hourglass id is a number (the letter O typed for 0 among them), names nothing (REF009).
// `hourglasses`: the deck's *HOURGLASS ids, read once for every part.
void check_hourglass(const RuleContext& c, const model::Part& part, std::optional<DefinedIds>& hourglasses,
                     MissingIds& missing) {
    const auto& h = part.hourglass;
    if (c.model.radioss || !h.explicit_value || h.value.empty() || h.value == "0") return;
    if (!hourglasses) hourglasses = defined_ids(c.deck, "HOURGLASS");
    if (hourglasses->unreadable) return;
    long long number = 0;
    const auto [end, ec] = std::from_chars(h.value.data(), h.value.data() + h.value.size(), number);
    const bool numeric = ec == std::errc() && end == h.value.data() + h.value.size();
    if (numeric && hourglasses->ids.count(number)) return;
    const std::optional<std::string> digits = numeric ? std::nullopt : letter_o_digits(h.value);
    missing.add("REF009", h.value, part, h.span,
                fmt::format("part {} names hourglass {} (HGID), which no *HOURGLASS defines{}", part.id, h.value,
                            letter_o_words(digits)),
                "HGID", std::nullopt, {}, letter_o_fix(digits, h.span));
}

// A part names `named`, which no definition holds, but `definitions` hold it with the letter O typed for a 0
// ("1O" for 10): the mistake is the definition's. Its finding is placed there (the part's field a note), the
// digits an unsafe fix, and the definition counts as used (no REF007). False when there is none.
template <typename Definition>
bool blame_letter_o_definition(const std::vector<Definition>& definitions, std::string_view code,
                               const model::Part& part, const model::Setting<Id>& named, std::string_view what,
                               std::string_view keyword, MissingIds& missing, std::set<Id>& used) {
    const Definition* d = letter_o_definition(definitions, named.value);
    if (!d) return false;
    missing.add_at_definition(code, named.value, part, named.span, d->span,
                              fmt::format("{} id {} holds the letter O for the digit 0: LS-DYNA reads the label {}, "
                                          "so part {} names {} {}, which no {} defines",
                                          what, d->id, d->id, part.id, what, named.value, keyword),
                              letter_o_fix(letter_o_digits(d->id), d->span));
    used.insert(d->id);
    return true;
}

void check_part_references(RuleContext& c, std::set<Id>& used_sections, std::set<Id>& used_materials,
                           std::set<Id>& used_eos) {
    MissingIds missing;
    const ThermalMaterialIds thermal = thermal_material_ids(c.deck);
    std::optional<DefinedIds> hourglasses;
    for (const model::Part& part : c.model.parts) {
        const auto& s = part.section;
        if (s.explicit_value && !c.model.section(s.value)) {
            if (!blame_letter_o_definition(c.model.sections, "REF003", part, s, "section", words(c).section, missing,
                                           used_sections))
                missing.add("REF003", s.value, part, s.span,
                            missing_reference(part, words(c).section_field, "section", s.value, words(c).section));
        } else if (s.explicit_value && !c.definitions().section_of(part))
            missing.add("REF003", s.value, part, s.span, missing_in_case(c, part, "section", s.value), "case");
        used_sections.insert(s.value);
        const auto& m = part.material;
        if (m.explicit_value && !c.model.material(m.value) &&
            !(m.value == "0" && needs_no_structural_material(c, part))) {
            if (!blame_letter_o_definition(c.model.materials, "REF004", part, m, "material", words(c).material, missing,
                                           used_materials))
                missing.add("REF004", m.value, part, m.span,
                            missing_reference(part, words(c).material_field, "material", m.value, words(c).material));
        } else if (m.explicit_value && c.model.material(m.value) && !c.definitions().material_of(part))
            missing.add("REF004", m.value, part, m.span, missing_in_case(c, part, "material", m.value), "case");
        used_materials.insert(m.value);
        const auto& e = part.eos;
        if (!e.value.empty() && !c.model.eos(e.value) &&
            !blame_letter_o_definition(c.model.equations_of_state, "REF005", part, e, "EOS", words(c).eos, missing,
                                       used_eos))
            missing.add("REF005", e.value, part, e.span,
                        fmt::format("part {} names EOS {}, which no {} defines", part.id, e.value, words(c).eos));
        used_eos.insert(e.value);
        check_thermal_material(c, part, thermal, missing);
        check_hourglass(c, part, hourglasses, missing);
    }
    missing.report(c);
}

// Set references: the keyword, the field holding the set id, and when it is a set.
void check_set_references(RuleContext& c) {
    for (const model::KeywordRecord& r : c.model.records) {
        const std::string_view k = r.schema->name;
        auto need = [&](std::string_view field, bool part_kind, std::string_view why) {
            const model::FieldRecord* f = r.field(field);
            if (!f || !f->explicit_value || !f->valid || f->number == 0) return;
            // The number read (a &name stands for its value), as the generated keywords' REF008 reads it.
            const auto number = static_cast<long long>(f->number);
            Id id = std::to_string(number);
            if (part_kind ? c.part_set(id) : c.node_set(id)) return;
            // Sets sphdeck does not expand (*SET_NODE_GENERAL, _ADD, _BOX...) define the id too.
            if (deck_may_define(c.deck, part_kind ? "SET_PART" : "SET_NODE", number)) return;
            c.report("REF008", f->span,
                     fmt::format("{} {} is not defined{}", part_kind ? "part set" : "node set", id, why));
        };
        auto number = [&](std::string_view field, double fallback) {
            const model::FieldRecord* f = r.field(field);
            return f && f->valid ? f->number : fallback;
        };
        if (k == "*INITIAL_VELOCITY") {
            need("NSID", false, "");
            need("NSIDEX", false, "");
        } else if (k == "*BOUNDARY_SPH_FLOW") {
            double styp = number("STYP", 1);
            if (styp == 1) need("ID", true, " (STYP 1)");
            if (styp == 3) need("ID", false, " (STYP 3)");
        } else if (k == "*DEFINE_SPH_TO_SPH_COUPLING") {
            if (number("SATYP", 0) == 0) need("SIDA", true, " (SATYP 0)");
            if (number("SBTYP", 0) == 0) need("SIDB", true, " (SBTYP 0)");
        } else if (k == "*DEFINE_ADAPTIVE_SOLID_TO_SPH") {
            if (number("ITYPE", 0) != 0) need("IPID", true, " (ITYPE not 0)");
        }
    }
}

// Where a list set names `id`: the member field holding it (a _GENERATE range: its first bound), found in
// the set's block, whose SID field is `set.span`; the SID when the block is not found.
grammar::Span member_span(const RuleContext& c, const model::IdSet& set, long long id) {
    for (const model::KeywordRecord& r : c.model.records) {
        const model::FieldRecord* sid = r.field("SID");
        if (!sid || sid->span.file != set.span.file || sid->span.line != set.span.line ||
            sid->span.column != set.span.column)
            continue;
        const bool generate = r.has_option("GENERATE");
        for (const auto& row : r.rows) {
            if (row.empty() || row.front().name == "TITLE" || row.front().name == "SID") continue;
            for (std::size_t k = 0; k < row.size(); k += generate ? 2 : 1) {
                if (!row[k].explicit_value || !row[k].valid) continue;
                const double first = row[k].number;
                const double last = generate && k + 1 < row.size() ? row[k + 1].number : first;
                if (first <= static_cast<double>(id) && static_cast<double>(id) <= last) return row[k].span;
            }
        }
        break;
    }
    return set.span;
}

void check_set_members(RuleContext& c, const model::IdIndex& nodes) {
    for (const auto& s : c.model.node_sets) {
        std::vector<long long> missing;
        for (long long id : s.members)
            if (!nodes.find(id)) missing.push_back(id);
        if (!missing.empty())
            c.report("REF001", s.span,
                     fmt::format("node set {} names undefined node(s) {}", s.id, listed_reference_ids(missing)));
    }
    for (const auto& s : c.model.part_sets) {
        std::vector<long long> missing;
        for (long long id : s.members)
            if (!c.model.part(std::to_string(id))) missing.push_back(id);
        // At the member that names the first missing part: the line a person edits (the SID is a note).
        if (!missing.empty())
            c.report("REF002", member_span(c, s, missing.front()),
                     fmt::format("part set {} names undefined part(s) {}", s.id, listed_reference_ids(missing)))
                .notes.push_back({s.span, fmt::format("part set {} is defined here", s.id)});
    }
}

// Boxes are referenced from fields named after them (BOXID, IBOXA, IBOXB) in other keywords.
std::set<Id> referenced_boxes(const model::Model& m) {
    std::set<Id> used;
    for (const model::KeywordRecord& r : m.records) {
        if (r.schema->name.rfind("*DEFINE_BOX", 0) == 0) continue;
        for (const auto& row : r.rows)
            for (const auto& f : row)
                if ((f.name == "BOXID" || f.name == "IBOXA" || f.name == "IBOXB") && f.explicit_value && f.number != 0)
                    used.insert(model::normalise_id(f.text));
    }
    return used;
}

template <typename T>
void report_unused(RuleContext& c, const std::vector<T>& items, const std::set<Id>& used, std::string_view what) {
    for (const T& item : items)
        if (!item.id.empty() && !used.count(item.id))
            c.report("REF007", item.span, fmt::format("{} {} is not used by any part", what, item.id));
}

}  // namespace

// An include that could not be read (DK010) may define any node, part, section, material, EOS or
// set the deck names, and use any the deck defines: "undefined" and "unused" cannot be told apart
// from "in the missing file", so those findings would only echo DK010 once per id.
bool include_missing(const RuleContext& c) {
    for (const diag::Diagnostic& d : c.deck.diagnostics)
        if (d.code == "DK010") return true;
    return false;
}

void check_references(RuleContext& c) {
    const model::IdIndex& nodes = c.node_index();
    const bool complete = !include_missing(c);
    if (complete) {
        check_particles(c, nodes);
        check_set_members(c, nodes);
    }
    check_node_duplicates(c, nodes);
    check_particle_duplicates(c);
    const model::CaseBlocks cases(c.deck);
    check_duplicates(c, cases, c.model.parts, "part");
    check_duplicates(c, cases, c.model.sections, "section");
    check_duplicates(c, cases, c.model.materials, "material");
    check_duplicates(c, cases, c.model.equations_of_state, "EOS");
    check_duplicates(c, cases, c.model.boxes, "box");
    check_thermal_material_duplicates(c, cases);
    if (!complete) return;
    std::set<Id> sections, materials, eos;
    check_part_references(c, sections, materials, eos);
    // *DEFINE_ADAPTIVE_SOLID_TO_SPH gives its new particles a section of their own (ISSPH).
    for (const model::KeywordRecord& r : c.model.records)
        if (const model::FieldRecord* f =
                r.schema->name == "*DEFINE_ADAPTIVE_SOLID_TO_SPH" ? r.field("ISSPH") : nullptr)
            if (f->explicit_value) sections.insert(model::normalise_id(f->text));
    // Sections and materials that generated keywords name (*DEFINE_SPH_MESH_SURFACE SPHXID...) are used.
    for (const model::IdReference& r : c.model.id_references) {
        if (r.kind == "SECTION") sections.insert(std::to_string(r.id));
        if (r.kind == "MAT") materials.insert(std::to_string(r.id));
    }
    check_set_references(c);
    report_unused(c, c.model.sections, sections, "section");
    report_unused(c, c.model.materials, materials, "material");
    report_unused(c, c.model.equations_of_state, eos, "EOS");
    std::set<Id> boxes = referenced_boxes(c.model);
    check_followed_references(c, boxes);
    for (const auto& b : c.model.boxes)
        if (!b.id.empty() && !boxes.count(b.id))
            c.report("REF007", b.span, fmt::format("box {} is not referenced", b.id));
}

}  // namespace sphdeck::lint
