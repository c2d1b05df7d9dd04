# rtlab: the two commands of the quick start are `make grade` and `make test`. Every target
# installs what is missing first (scripts/install-deps, Debian packages) and builds.
#
#   make grade [IMPL=assignments|solutions]   grade the student tree (or the reference)
#   make test                                 the whole test suite through ctest (installs Blender
#                                             too: the radiometry references' tests render with it)
#   make test-sanitize                        the suite under AddressSanitizer + UBSan
#   make bench                                benchmarks against Embree (docs/performance.md)
#   make gradescope                           the Gradescope autograder zip
#   make fuzz [FUZZ_SECONDS=60]               every libFuzzer target for that long (fuzz/README.md)
#   make test-tsan                            renders, hit traces and the bench under ThreadSanitizer
#   make validate-gltf                        gltf-validator on every glTF shipped or written
#   make test-batch-engines                   a sharded batch through GNU parallel and a local Slurm

MAKEFLAGS += --no-print-directory
IMPL ?= assignments
JOBS ?= $(shell nproc)
RTLAB := build/$(if $(filter solutions,$(IMPL)),rtlab-solution,rtlab)

.PHONY: deps deps-blender build models grade test test-sanitize test-batch-engines bench gradescope clean fuzz fuzz-ci test-tsan validate-gltf

deps:
	@scripts/install-deps

# Blender is large (about 340 MB) and only the instructor's references and the test suite use
# it: make grade never installs it.
deps-blender:
	@scripts/install-deps --blender

build: deps
	@mkdir -p build && cmake --preset release > build/configure.log || (cat build/configure.log; exit 1)
	@cmake --build --preset release -j $(JOBS)

models: build
	@scripts/fetch-models build/models

# Only what grading needs: the command, the grader and the worker with the code to grade.
GRADE_TARGETS := $(notdir $(RTLAB)) rtlab-grader $(if $(filter solutions,$(IMPL)),rtlab-worker-solution,rtlab-worker)
grade: deps
	@mkdir -p build && cmake --preset release > build/configure.log || (cat build/configure.log; exit 1)
	@scripts/quiet-build build/grade-build.log cmake --build --preset release -j $(JOBS) --target $(GRADE_TARGETS)
	@scripts/fetch-models build/models
	@$(RTLAB) grade

test: deps-blender build models
	@ctest --preset release -j $(JOBS)

test-sanitize: deps
	@mkdir -p build-sanitize && cmake --preset sanitize > build-sanitize/configure.log || (cat build-sanitize/configure.log; exit 1)
	@cmake --build --preset sanitize -j $(JOBS)
	@scripts/fetch-models build-sanitize/models
	@ctest --preset sanitize -j $(JOBS) -L sanitize

# Its own build (preset bench: -march=native, as the anchors' harness compiled its peers), so
# the figures compare with the anchors (docs/performance.md#what-is-measured); the student
# build stays portable.
bench: deps
	@mkdir -p build-bench && cmake --preset bench > build-bench/configure.log || (cat build-bench/configure.log; exit 1)
	@cmake --build --preset bench -j $(JOBS) --target rtlab-solution rtlab-solution-bench
	@scripts/fetch-models build-bench/models
	@build-bench/rtlab-solution bench --out build-bench/bench-results

gradescope: build
	@scripts/make-gradescope build/gradescope.zip

# The parsers of outside input under libFuzzer (clang, build-fuzz/); fuzz-ci is CI's short run.
FUZZ_SECONDS ?= 60
fuzz: deps
	@JOBS=$(JOBS) fuzz/run-fuzzers $(FUZZ_SECONDS)

fuzz-ci: deps
	@JOBS=$(JOBS) fuzz/run-fuzzers 20

# Its own build (preset tsan, build-tsan/): only the executables scripts/run-tsan runs.
test-tsan: deps
	@mkdir -p build-tsan && cmake --preset tsan > build-tsan/configure.log || (cat build-tsan/configure.log; exit 1)
	@cmake --build --preset tsan -j $(JOBS) --target rtlab-solution rtlab-solution-bench
	@scripts/run-tsan build-tsan

validate-gltf: build models
	@scripts/validate-gltf-all build

# docs/grading.md "Course scale": both fan-out recipes on three small submissions (about a
# minute; starts and stops its own single-node Slurm, so it needs root).
test-batch-engines: build
	@timeout 900 tests/cli/batch_engines.sh build $(CURDIR)

clean:
	rm -rf build build-debug build-sanitize build-bench build-fuzz build-tsan build-configure*.log
