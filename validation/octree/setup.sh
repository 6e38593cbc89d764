# Sourced by run.sh and surfaces.sh, with ROOT and BUILD set.
# install_missing PACKAGE...: installs those of the Debian packages not installed yet.
# build_volmesh: the Release volmesh in $BUILD (VOLMESH) and libcgal-demo's meshes unpacked
# there (MESHES).
install_missing() {
  local need=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || need+=("$p")
  done
  [ ${#need[@]} -eq 0 ] && return 0
  local sudo
  sudo=$([ "$(id -u)" = 0 ] || echo sudo)
  echo "installing: ${need[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}"
}

build_volmesh() {
  mkdir -p "$BUILD"
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release > "$BUILD/configure.log"
  cmake --build "$BUILD" -j "$(nproc)" --target volmesh > "$BUILD/build.log" 2>&1
  VOLMESH=$BUILD/apps/volmesh/volmesh
  MESHES=$BUILD/cgal-data/data/meshes
  if [ ! -f "$MESHES/knot1.off" ]; then
    mkdir -p "$BUILD/cgal-data"
    tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$BUILD/cgal-data" data/meshes
  fi
}
