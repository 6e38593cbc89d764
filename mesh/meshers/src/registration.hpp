#pragma once
// How a method's file adds it to the registry, at namespace scope:
//   const Registration registered{MesherInfo{...}};
// The module is an OBJECT library, so that every method's file is linked into each program
// using it and registers before main; registering one name twice aborts at start-up.
#include "volmesh/meshers/registry.hpp"

namespace volmesh::meshers {

struct Registration {
  explicit Registration(MesherInfo info);
};

}  // namespace volmesh::meshers
