#pragma once
// A back end's shot figures (ShotStats::figures, JSON) drawn in the panel without knowing the back
// end: numbers as lines, arrays of counts as histograms, arrays of objects as tables, objects as
// folding groups.
#include <nlohmann/json.hpp>
#include <string>

namespace radmesh {

bool isHistogram(const nlohmann::json& value);  // an array of counts
bool isTable(const nlohmann::json& value);      // an array of objects, one a row

void figureHistogram(const std::string& key, const nlohmann::json& counts);
// Its columns: the first row's keys, the names (strings) before the numbers.
void figureTable(const std::string& key, const nlohmann::json& rows);
// A group of figures (an object), folded: its numbers, and its groups inside.
void figureGroup(const std::string& key, const nlohmann::json& group);

}  // namespace radmesh
