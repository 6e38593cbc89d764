#pragma once
// The hexdc mesher's figures (volmesh/hexdc/mesher.hpp's HexdcResult) as `volmesh mesh --json`
// prints them, the paper's Table 1 columns under "stages".
#include <nlohmann/json.hpp>

#include "volmesh/hexdc/mesher.hpp"

namespace volmesh::meshers {

nlohmann::json hexdc_summary(const HexdcResult& result);

}  // namespace volmesh::meshers
