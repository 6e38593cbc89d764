# volmesh_petsc_unsupported(<out> <include dirs>...): what the PETSc whose petscconf.h lies in
# one of the include dirs has that volmesh's PETSc backend cannot take ("64-bit indices",
# "complex scalars"), empty when it has neither. The backend hands PETSc the 32-bit indices
# of its meshes and reads real solutions.
function(volmesh_petsc_unsupported out)
  set(_found "")
  foreach(_dir IN LISTS ARGN)
    if(EXISTS "${_dir}/petscconf.h")
      file(STRINGS "${_dir}/petscconf.h" _kinds
           REGEX "^#define PETSC_USE_(64BIT_INDICES|COMPLEX) ")
      if(_kinds MATCHES "PETSC_USE_64BIT_INDICES")
        list(APPEND _found "64-bit indices")
      endif()
      if(_kinds MATCHES "PETSC_USE_COMPLEX")
        list(APPEND _found "complex scalars")
      endif()
      break()
    endif()
  endforeach()
  list(JOIN _found " and " _found)
  set(${out} "${_found}" PARENT_SCOPE)
endfunction()
