// smoothing_preview: per part what `sphdeck smooth` shows: particles, spacing, initial smoothing length
// and its bounds, neighbour counts, sound speed and time step estimates, and the notes on what is missing.
#include <memory>

#include "mcp/deck_input.hpp"
#include "preproc/preview.hpp"
#include "preproc/preview_json.hpp"
#include "preproc/sph_mesh_box.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

ToolResult run_smooth_tool(const Arguments& args, const ToolContext& context) {
    const DeckInput deck = deck_input(args, context);
    engine::CheckOptions options = check_options(deck, context);
    const auto ini = args.number("ini");
    options.rules.keep_preview = !ini.has_value();  // the rules' own preview, unless another INI is asked for
    const engine::CheckResult r = engine::check_deck(deck.path, deck.documents, options);
    confine_reads(r, context);
    const preproc::MeshBoxParticles boxes = preproc::generate_mesh_box_particles(r.model);
    const model::Model extended = boxes.size() ? preproc::with_mesh_box_particles(r.model, boxes) : model::Model{};
    const model::Model& model = boxes.size() ? extended : r.model;
    if (model.particles.size() == 0)
        throw ToolFailure("the deck has no SPH particles (*ELEMENT_SPH): nothing to preview");
    std::shared_ptr<const preproc::Preview> preview = boxes.size() ? nullptr : r.preview;
    if (!preview) {
        preproc::PreviewOptions preview_options;
        if (ini) preview_options.ini = static_cast<model::IniMode>(static_cast<int>(*ini));
        preview = std::make_shared<const preproc::Preview>(preproc::compute_preview(model, preview_options));
    }
    json parts = json::array();
    for (const preproc::PartPreview& p : preview->parts) parts.push_back(json(preproc::part_preview_json(p)));
    json structured = {{"dimension", preview->dimension},
                       {"particles", model.particles.size()},
                       {"coincident_pairs", preview->coincident_pairs},
                       {"parts", std::move(parts)},
                       {"findings", counts_json(r.diagnostics)}};
    return {std::move(structured), {}};
}
}  // namespace

Tool smoothing_preview_tool() {
    json properties = deck_schema_properties("deck");
    properties["ini"] = {{"type", "integer"},
                         {"minimum", 0},
                         {"maximum", 2},
                         {"description",
                          "initial smoothing length mode instead of the deck's *CONTROL_SPH INI: 0 "
                          "bucket sort, 1 global search, 2 from the mass"}};
    json schema = {{"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
    return {"smoothing_preview", "Preview smoothing lengths",
            "Previews what the solver will compute at the start, per SPH part, as `sphdeck smooth` does: particle "
            "spacing, initial smoothing length h0 and its bounds, kernel support, neighbour counts, sound speed and "
            "time step estimates, with notes on any value that cannot be computed.",
            std::move(schema), run_smooth_tool};
}

}  // namespace sphdeck::mcp
