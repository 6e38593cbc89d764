#pragma once
// The meshers build and drop tables of tens of megabytes pass after pass. glibc hands large
// blocks back to the system on free, and every pass would pay its page faults again (up to
// a tenth of a run); kept in the heap, they are reused. Called once by the programs that
// mesh (the command, the Python module).
namespace volmesh::cli {

void keep_freed_memory();

}  // namespace volmesh::cli
