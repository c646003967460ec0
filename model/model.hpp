// The format-neutral model (design.md, "model/ is the seam"): what the lint rules, the preview
// and the solver read. LS-DYNA and (later) Radioss decks both land here.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "text/source_map.hpp"
#include "model/id_column.hpp"
#include "model/id_links.hpp"
#include "model/particle_lines.hpp"
#include "model/radioss_facts.hpp"
#include "model/settings.hpp"

namespace sphdeck::model {

// A value the deck may set: its value (the default when not given), whether the deck wrote it,
// and where (the field's columns; for a default, the keyword line).
template <typename T>
struct Setting {
    T value{};
    bool explicit_value = false;
    grammar::Span span;

    Setting() = default;
    Setting(T default_value) : value(std::move(default_value)) {}  // NOLINT: a default reads naturally
    Setting(T v, bool given, grammar::Span where) : value(std::move(v)), explicit_value(given), span(where) {}
};

// One decoded field of a keyword instance, kept for `sphdeck dump` and for rules that need a
// field no typed struct carries.
struct FieldRecord {
    std::string_view name;  // from the schema (static storage)
    keywords::FieldType type = keywords::FieldType::Integer;
    double number = 0.0;
    std::string text;
    bool explicit_value = false;
    bool valid = false;
    grammar::Span span;
};

// One keyword block (not *NODE / *ELEMENT_SPH: those go to the particle arrays). Repeated
// cards (curve points, set ids, parts) are kept in `rows`, one per line.
struct KeywordRecord {
    const keywords::KeywordSchema* schema = nullptr;
    std::string keyword;                         // as written, upper case: "*SECTION_SPH_ELLIPSE"
    std::vector<std::string_view> options;       // option suffixes given
    grammar::Span span;                          // the keyword name
    std::vector<std::vector<FieldRecord>> rows;  // one per decoded card line

    // The first field of that name in the block (over all rows), or nullptr.
    const FieldRecord* field(std::string_view name) const;
    bool has_option(std::string_view suffix) const;
};

// Ids of parts, sections, materials and EOS may be labels (971 R7.1): kept as text, with
// numbers normalised ("0001" and "1" are the same id).
using Id = std::string;

struct ControlSph {
    bool present = false;
    grammar::Span keyword;
    Setting<long long> ncbs{1}, boxid{0}, memory{150}, cont{0}, deriv{0}, ishow{0}, icont{0}, isymp{100};
    Setting<long long> ithk{0}, istab{0}, sphsort{0}, ishift{0};
    Setting<double> dt{1.0e20}, start{0.0}, maxv{1.0e15}, ql{0.01};
    Setting<Dimension> idim{Dimension::Unset};
    Setting<Form> form{Form::Default};
    Setting<IniMode> ini{IniMode::BucketSort};
    Setting<ErosionMode> ierod{ErosionMode::StayActive};
    Setting<ArtificialViscosity> iavis{ArtificialViscosity::Monaghan};
};

struct Controls {
    ControlSph sph;
    Setting<double> endtim{0.0};        // *CONTROL_TERMINATION
    Setting<double> tssfac{0.9};        // *CONTROL_TIMESTEP
    Setting<long long> erode{0};        // *CONTROL_TIMESTEP ERODE
    Setting<double> q1{1.5}, q2{0.06};  // *CONTROL_BULK_VISCOSITY
    bool bulk_viscosity_present = false;
    std::vector<grammar::Span> mpp_keywords;  // *CONTROL_MPP_* blocks: evidence of an MPP run
    Setting<long long> soln{0};               // *CONTROL_SOLUTION: 0 structural, 1 thermal only, 2 coupled
};

struct Section {
    Id id;
    std::string keyword;  // "*SECTION_SPH", "*SECTION_SPH_ELLIPSE", "*SECTION_SHELL"...
    bool sph = false, ellipse = false, interaction = false;
    grammar::Span span;  // the SECID field
    Setting<double> cslh{1.2}, hmin{0.2}, hmax{2.0}, sphini{0.0}, death{1.0e20}, start{0.0};
    Setting<Kernel> kernel{Kernel::CubicSpline};
    long long shell_form = 0;  // *SECTION_SHELL ELFORM as written (12-15: 2D solids), 0 when not read
};

struct Part {
    Id id;
    std::string heading;
    grammar::Span span;  // the PID field
    Setting<Id> section, material, eos, hourglass, thermal_material;
    bool inertia = false;  // *PART_INERTIA: mass and inertia given, not taken from the density
};

struct Material {
    Id id;
    std::string keyword;  // canonical when known ("*MAT_NULL"), else as written
    grammar::Span span;
    Setting<double> density;
    std::optional<std::size_t> record;  // index into Model::records, when the schema knows it
    // The layout has a density the solver requires (RO; Radioss RHO_I of a law the starter checks):
    // false for *MAT_ springs without RO, /MAT/VOID, the multi-material laws (SPH119).
    bool has_density = false;
};

struct Eos {
    Id id;
    std::string keyword;
    grammar::Span span;
    std::optional<std::size_t> record;  // index into Model::records, when the schema knows it
};

struct Box {
    Id id;
    grammar::Span span;
    std::array<double, 6> bounds{};  // xmin, xmax, ymin, ymax, zmin, zmax
};

struct SymmetryPlane {
    std::array<double, 3> tail{}, head{};  // the normal points from tail to head, into the body
    grammar::Span span;
};

struct IdSet {
    Id id;
    grammar::Span span;
    std::vector<long long> members;
    bool truncated = false;  // a _GENERATE range far larger than the model was not expanded fully
};

// Particles and nodes as structure-of-arrays: decks of 1e7 particles are normal. Ids in 4 bytes
// while they fit (model/id_column.hpp), each particle's line as runs (model/particle_lines.hpp):
// 45 bytes a particle with its node, as long as the ids fit.
// No per-node line index: nodes are 10^7 in big decks and their lines are needed only for the
// rare duplicate report, which finds them by scanning (RuleContext::node_lines).
struct Nodes {
    IdColumn id;
    std::vector<double> x, y, z;
};

struct Particles {
    IdColumn node;                     // node id (= element id)
    IdColumn part;                     // PID as an integer (-1 when it could not be read: DK002)
    std::vector<double> mass;          // > 0 mass; < 0 |mass| is a volume
    std::vector<std::uint8_t> volume;  // 1 when *ELEMENT_SPH_VOLUME: mass holds a volume
    ParticleLines line;                // index into RawDeck::lines
    std::size_t size() const { return node.size(); }
};

struct Model {
    // Declared here and defaulted in model/model.cpp: the special members of this large aggregate are compiled
    // once, not in every room that copies, moves or drops one (issue 42).
    Model();
    Model(const Model&);
    Model(Model&&) noexcept;
    Model& operator=(const Model&);
    Model& operator=(Model&&) noexcept;
    ~Model();

    std::vector<KeywordRecord> records;  // every known keyword block but *NODE/*ELEMENT_SPH
    Controls controls;
    std::vector<Section> sections;
    std::vector<Part> parts;
    std::vector<Material> materials;
    std::vector<Eos> equations_of_state;
    std::vector<Box> boxes;
    std::vector<SymmetryPlane> symmetry_planes;
    std::vector<IdSet> node_sets, part_sets;
    std::vector<IdReference> id_references;  // ids named by generated keywords (model/id_links.hpp)
    Nodes nodes;
    Particles particles;
    bool memory2_given = false;           // memory2= on *KEYWORD: MPP evidence
    std::optional<RadiossFacts> radioss;  // set for Radioss decks only (model/radioss_facts.hpp)

    const Part* part(const Id& id) const;
    const Section* section(const Id& id) const;
    const Material* material(const Id& id) const;
    const Eos* eos(const Id& id) const;
    const Box* box(const Id& id) const;
};

// "0001" → "1"; labels stay as written (trimmed).
Id normalise_id(std::string_view text);

// The builders' last step: node ids, particle nodes and parts that run first + step * i kept as those two
// numbers (IdColumn::compact), 12 bytes a particle with its node less through the rest of a check, whose
// peak of memory is the geometry preview's (issue 40).
void compact_bulk_ids(Model& model);

}  // namespace sphdeck::model
