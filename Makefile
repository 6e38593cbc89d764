# The two commands of the README: `make demo` (the main job) and `make test` (build and pass
# the tests). Both install the Debian 12 packages they need when missing.
SHELL := /bin/bash
BUILD := build/release
ASAN_BUILD := build/asan
JOBS ?= $(shell nproc)
# PCH=ON precompiles the headers most files parse: a cold build takes far less
# CPU, but ccache cannot share those objects between build trees. Unset, a tree keeps its
# setting (off when first configured).
PCH ?=
CMAKE_OPTIONS := $(if $(PCH),-DVOLMESH_PCH=$(PCH))

BUILD_PACKAGES := cmake ninja-build g++ ccache pkg-config libeigen3-dev libcgal-dev libgmp-dev \
  libmpfr-dev libvtk9-dev libmetis-dev libgtest-dev libcli11-dev nlohmann-json3-dev \
  libtbb-dev zlib1g-dev libmuparser-dev libgd-dev petsc-dev libhypre-dev openmpi-bin \
  libopenmpi-dev libp4est-dev
# The Python module (python/): pybind11 for Debian's python3, numpy for its arrays.
PYTHON_PACKAGES := python3-dev pybind11-dev python3-pybind11 python3-numpy
BUILD_PACKAGES += $(PYTHON_PACKAGES)
# Third-party readers the round-trip tests check our output with (VTK's parallel reader for
# the distributed solve's PVTU), and the test surfaces.
TEST_PACKAGES := python3 python3-meshio python3-vtk9 gmsh openfoam libcgal-demo
# The Python module's tests.
TEST_PACKAGES += python3-pytest

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
missing = $(shell for p in $(1); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done)

.PHONY: demo test test-sanitize build build-sanitize deps-build deps-test clean

deps-build:
	@m="$(call missing,$(BUILD_PACKAGES))"; if [ -n "$$m" ]; then \
	  echo "installing: $$m"; $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$m; fi

deps-test: deps-build
	@m="$(call missing,$(TEST_PACKAGES))"; if [ -n "$$m" ]; then \
	  echo "installing: $$m"; $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$m; fi

build: deps-build
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_OPTIONS)
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/volmesh/volmesh demo -o demo-output

# --timeout: the limit of any test that does not set its own (tests/CMakeLists.txt sets 600 s).
TEST_TIMEOUT := 600

test: deps-test build
	ctest --test-dir $(BUILD) --output-on-failure --timeout $(TEST_TIMEOUT) -j $(JOBS)

# The unit tests once more under AddressSanitizer + UndefinedBehaviorSanitizer (CI runs it
# after `make test`); any report fails the run. Its tree builds only the `unit` tests'
# executables and what they link or run (the volmesh binary, for the command-line tests).
build-sanitize: deps-build
	cmake -S . -B $(ASAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DVOLMESH_SANITIZE=ON $(CMAKE_OPTIONS) \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g"
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target tests_unit

test-sanitize: deps-test build-sanitize
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(ASAN_BUILD) --output-on-failure --timeout $(TEST_TIMEOUT) -j $(JOBS) -L unit

clean:
	rm -rf build demo-output
