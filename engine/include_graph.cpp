#include "engine/include_graph.hpp"

#include <algorithm>

#include "engine/documents.hpp"

namespace sphdeck::engine {

bool IncludeGraph::depends_on(const std::filesystem::path& path) const {
    const std::filesystem::path key = Documents::key(path);
    return key == main || std::any_of(files.begin(), files.end(), [&](const IncludedFile& f) { return f.path == key; });
}

IncludeGraph include_graph(const grammar::SourceMap& sources) {
    IncludeGraph graph;
    if (sources.size() == 0) return graph;
    std::vector<std::filesystem::path> keys;  // one per source file, computed once
    keys.reserve(sources.size());
    for (grammar::FileId id = 0; id < sources.size(); ++id) keys.push_back(Documents::key(sources.file(id).path));
    graph.main = keys[0];
    for (grammar::FileId id = 1; id < sources.size(); ++id) {
        const grammar::SourceFile& file = sources.file(id);
        IncludedFile f{keys[id], file.display_name, {}, file.include_line};
        if (file.parent != grammar::no_file && file.parent < keys.size()) f.included_by = keys[file.parent];
        graph.files.push_back(std::move(f));
    }
    return graph;
}

}  // namespace sphdeck::engine
