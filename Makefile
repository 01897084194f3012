# SPDX-License-Identifier: BSD-2-Clause
# The two commands: `make run` and `make test`. Both install what is missing, configure and build.
BUILD ?= build
SCENE ?= inputs/sod_weak.opts
OUT   ?= output/sod_weak
NP    ?= 1
PY    ?= /usr/bin/python3
MPIEXEC = mpiexec --allow-run-as-root --oversubscribe

.PHONY: all deps configure build run test bench methods verification clean format
all: build

deps:
	@scripts/install-deps.sh

$(BUILD)/build.ninja: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD)

run: build
	$(MPIEXEC) -n $(NP) $(BUILD)/petmpm -options_file $(SCENE) -mpm_output $(OUT) -mpm_report $(OUT)/report.json
	$(PY) scripts/plot_profiles.py $(OUT)/petmpm.h5 $(OUT)/profiles.png
	$(PY) scripts/summary.py $(OUT)/report.json
	@echo "Profiles plotted against the exact solution: $(OUT)/profiles.png"
	@echo "HDF5: $(OUT)/petmpm.h5   ParaView/VisIt: $(OUT)/petmpm.xmf   report: $(OUT)/report.json"

test: build
	cd $(BUILD) && ctest -j2 --output-on-failure

bench: build
	$(PY) scripts/bench.py

methods: build
	$(PY) scripts/methods.py --exe $(BUILD)/petmpm

# The study definitions of scripts/studies/ into docs/studies/NAME (cases already there are skipped; FRESH=1
# measures again), then docs/verification.md from their results; the expectation files of tests/studies/ (the
# finest resolutions of a test's comparison, too long for make test).
STUDIES = $(basename $(notdir $(wildcard scripts/studies/*.json)))
verification: build
	$(if $(FRESH),rm -rf $(addprefix docs/studies/,$(STUDIES)))
	for s in $(STUDIES); do $(PY) scripts/study --study scripts/studies/$$s.json --out docs/studies/$$s || exit 1; done
	$(PY) scripts/study --summary $(addprefix docs/studies/,$(STUDIES)) --markdown docs/verification.md
	for f in tests/studies/*.json; do $(PY) tests/run_scene.py $(BUILD) . $$f || exit 1; done
	$(BUILD)/petmpm -options_file inputs/flyer_plate.opts -mpm_output output/flyer_plate >/dev/null
	$(PY) scripts/plot_profiles.py output/flyer_plate/petmpm.h5 docs/verification_flyer_profiles.png
	$(PY) scripts/hardcases.py --exe $(BUILD)/petmpm --out docs/hard-cases.md
	$(PY) scripts/taylor.py --exe $(BUILD)/petmpm
	$(PY) scripts/dambreak.py --exe $(BUILD)/petmpm

format:
	clang-format -i $$(git ls-files '*.c' '*.h')

clean:
	rm -rf $(BUILD)
