# servo_bc: pure-C core, embedded runner, tests.
#   make          core libraries (static, shared) and the runner build/servo-bc
#   make demo     the paper's 25-particle (D) case on the embedded engine
#   make check    every test: core, ASan+UBSan build, valgrind, LAMMPS, LIGGGHTS, the hosts side by
#                 side, YADE, the FE^2 patch test (installs what it needs)
#   make lammps   build/lmp_servo: LAMMPS with fix servo_bc (Debian package)
#   make liggghts build/liggghts_servo: LIGGGHTS with fix servo_bc (Debian package)
#   make yade     the YADE engine's library (build/libservo_bc.so) and the Debian YADE package
#   make compare CASE=FILE.sbc   one case on every engine, report in out/compare/ (docs/cross-host.md)
#   make bench    benchmarks (prints figures; LAMMPS side when installed)
#   make figures  every figure and table of docs/reproduction-*.md, regenerated (hours; FIGURES=... for some)
#   make fe2-patch   the FE^2 patch test on GetFEM (docs/fe2.md)
#   make fe2-demo    the FE^2 biaxial test with (D), (P), (T) points beside a DNS: out/fe2/biaxial.csv, .svg
#   make fe2-demo3d  the 3D FE^2 triaxial test with (D), (P) points beside a DNS: out/fe2/triaxial.csv, .svg
#   make femxdem  FEMxDEM (YADE + escript) beside servo_bc's FE^2 on one of its RVEs: out/femxdem/side_by_side.md
#   make fuzz     libFuzzer campaigns over the core's input surfaces (FUZZ_RUNS per harness; docs/reliability.md)
#   make install PREFIX=/usr/local   the library, headers, runner, Python modules, docs, pkg-config and CMake
#                 files (DESTDIR too); make uninstall PREFIX=... removes them (docs/core.md, "Installing")

CC      ?= cc
CSTD     = -std=c11 -Wall -Wextra -pedantic -Werror
OPT     ?= -O2 -g
CFLAGS  += $(CSTD) $(OPT) -fPIC -Isrc_core/include -Isrc_core/src
LDLIBS   = -lm
B        = build
# the condensed tangent's sparse direct solver, UMFPACK (Debian libsuitesparse-dev), when its header is
# installed (scripts/install-deps.sh core installs it); without it the core builds and solves densely
# (docs/fe2.md). SPARSE=no builds without it anyway.
SPARSE  ?= $(if $(wildcard /usr/include/suitesparse/umfpack.h),yes,no)
ifeq ($(SPARSE),yes)
SPARSE_FLAGS = -DSBC_HAVE_UMFPACK -I/usr/include/suitesparse
LDLIBS      += -lumfpack
endif
CFLAGS  += $(SPARSE_FLAGS)

# the core by layer: servo (controller, frame, homogenization, grammar, host
# handle), engines (the embedded 2D and 3D engines, packings), io (results,
# VTK, plots), runner (the script language of servo-bc)
CORE_SRC = $(wildcard src_core/src/*/*.c)
CORE_HDR = $(wildcard src_core/include/sbc/*.h src_core/include/sbc/embedded/*.h src_core/src/*/*.h)
CORE_OBJ = $(CORE_SRC:src_core/src/%.c=$(B)/core/%.o)
TEST_SRC = $(wildcard tests/*.c)
# the servo-bc program's own sources beyond main.c: host syntax (the decks of
# --decks), which the core library does not write
RUNNER_SRC = src_core/runner/decks.c
TEST_HDR = $(wildcard tests/*.h)
# fuzz harnesses (fuzz/, docs/reliability.md)
FUZZ_NAMES  = settings packing script host restart
FUZZ_COMMON = fuzz/fuzz.h fuzz/private_folder.c fuzz/drive_controller.c fuzz/restart_case.h
FUZZ_REPLAY = $(FUZZ_NAMES:%=$(B)/fuzz/%_replay)
FUZZ_RUNS  ?= 1000000
# packings of 64 particles at most, so that an input runs in a few milliseconds
# under the sanitizers (a legitimate large packing is no finding)
FUZZ_FLAGS  = -std=c11 -O1 -g -fno-omit-frame-pointer -Isrc_core/include -Isrc_core/src -DSBC_PACKING_MAX=64L

.PHONY: all demo compare check check-core-and-sanitize deps install uninstall check-install check-core check-sanitize check-valgrind check-lammps check-liggghts check-cross-host \
  check-yade fe2-patch fe2-demo fe2-demo3d femxdem lammps liggghts fuzz figures \
  yade bench clean
all: $(B)/libservo_bc.a $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot

$(B)/core/%.o: src_core/src/%.c $(CORE_HDR) $(B)/sparse-$(SPARSE)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -c $< -o $@

# the objects are built again when SPARSE changes (the solver was installed or left out)
$(B)/sparse-$(SPARSE):
	@mkdir -p $(B) && rm -f $(B)/sparse-* && touch $@

figures: all
	bash scripts/figures.sh

$(B)/libservo_bc.a: $(CORE_OBJ)
	rm -f $@ && ar rcs $@ $^

# the shared library's SONAME names its major version (make install links libservo_bc.so.MAJOR to it)
VERSION := $(shell sed -n 's/^\#define SBC_VERSION "\(.*\)"/\1/p' src_core/include/sbc/version.h)
$(B)/libservo_bc.so: $(CORE_OBJ)
	$(CC) -shared -Wl,-soname,libservo_bc.so.$(firstword $(subst ., ,$(VERSION))) -o $@ $^ $(LDLIBS)

PREFIX ?= /usr/local
install: all
	bash scripts/install.sh install $(PREFIX) $(B) $(VERSION) "$(LDLIBS)"

uninstall:
	bash scripts/install.sh uninstall $(PREFIX)

# make install into a temporary prefix, used with pkg-config, CMake and pip (tests/install.sh)
$(B)/install-deps.installed:
	@mkdir -p $(B)
	@bash scripts/install-deps.sh install
	@touch $@

check-install: all $(B)/install-deps.installed
	bash tests/install.sh $(B) $(VERSION) "$(LDLIBS)"

$(B)/servo-bc: src_core/runner/main.c $(RUNNER_SRC) src_core/runner/decks.h $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -o $@ $< $(RUNNER_SRC) $(B)/libservo_bc.a $(LDLIBS)

$(B)/servo-bc-plot: src_core/runner/plot_main.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

$(B)/run_tests: $(TEST_SRC) $(TEST_HDR) $(RUNNER_SRC) $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -Itests -Isrc_core/src -Isrc_core/runner -o $@ $(TEST_SRC) $(RUNNER_SRC) $(B)/libservo_bc.a $(LDLIBS)

# The same tests, core compiled in, under AddressSanitizer + UBSan.
$(B)/run_tests_san: $(TEST_SRC) $(TEST_HDR) $(RUNNER_SRC) $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(B)
	$(CC) $(CSTD) $(SPARSE_FLAGS) -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
	  -Isrc_core/include -Isrc_core/src -Isrc_core/runner -Itests -o $@ $(TEST_SRC) $(RUNNER_SRC) $(CORE_SRC) $(LDLIBS)

demo: all
	@mkdir -p out/demo
	$(B)/servo-bc inputs/demo_D_25.sbc

# each part's wall time is printed after it (CI's budget is 30 minutes for all of them)
CHECK_PARTS = check-core-and-sanitize check-valgrind check-install check-lammps check-liggghts check-cross-host check-yade \
  fe2-patch
check: deps
	@start=$$(date +%s); failed=; for part in $(CHECK_PARTS); do begun=$$(date +%s); \
	  $(MAKE) --no-print-directory $$part || { failed="$$failed $$part"; [ -n "$(findstring k,$(firstword -$(MAKEFLAGS)))" ] || \
	    { echo "make check: $$part failed"; exit 1; }; }; \
	  echo "make check: $$part took $$(( $$(date +%s) - begun )) s"; done; \
	  echo "make check: all parts took $$(( $$(date +%s) - start )) s"; \
	  [ -z "$$failed" ] || { echo "make check: failed:$$failed"; exit 1; }

deps:
	@bash scripts/install-deps.sh core

# make check's first part: check-core and check-sanitize side by side on two cores (each runs its suites one after
# another; their scratch folders differ), each one's output printed whole when it ends (-O)
check-core-and-sanitize:
	@$(MAKE) --no-print-directory -j2 -O check-core check-sanitize

# every public header in one C++ translation unit, linked without a wrapper
$(B)/cxx_headers: tests/cxx_headers.cpp $(B)/libservo_bc.a $(wildcard src_core/include/sbc/*.h src_core/include/sbc/embedded/*.h)
	c++ -std=c++11 -Wall -Wextra -pedantic -Werror -Isrc_core/include -o $@ tests/cxx_headers.cpp $(B)/libservo_bc.a $(LDLIBS)

$(B)/fe2_example: inputs/fe2/material_point.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

check-core: $(B)/run_tests $(B)/servo-bc $(B)/servo-bc-plot $(B)/cxx_headers $(B)/libservo_bc.so $(B)/fuzz/restart_seed \
            $(B)/fe2_example
	$(B)/run_tests $(B)/servo-bc
	$(B)/fe2_example
	$(B)/cxx_headers
	bash tests/headers.sh
	bash tests/tables.sh $(B)
	python3 tests/docs_check.py .
	python3 tests/python_core.py $(B)/libservo_bc.so $(B)/servo-bc
	python3 tests/tangent_irregular.py $(B)/libservo_bc.so $(B)/servo-bc
	python3 tests/tangent_runner.py $(B)/servo-bc
	@echo "the core without the sparse solver (SPARSE=no): built, and the condensed tangent's tests"
	@$(MAKE) --no-print-directory -s B=$(B)/without-sparse SPARSE=no $(B)/without-sparse/run_tests
	@mkdir -p $(B)/without-sparse/tmp
	SBC_TEST_SUITE=condensed,point,interior $(B)/without-sparse/run_tests $(B)/servo-bc $(B)/without-sparse/tmp
	bash tests/layers.sh $(B)
	bash tests/restart_layout.sh $(B)
	bash tests/path_error.sh
	bash tests/splice_tables.sh
	bash tests/stability.sh $(B)
	bash tests/certify.sh $(B)
	bash tests/replicas.sh $(B)
	bash tests/traction_irregular.sh $(B)
	bash tests/traction_irregular_3d.sh $(B)
	bash tests/remap.sh $(B)
	bash tests/newton.sh $(B)

check-sanitize: $(B)/run_tests_san $(B)/servo-bc $(B)/servo-bc-plot $(FUZZ_REPLAY) $(B)/fuzz/corpus/restart/seed.bin
	@mkdir -p $(B)/test-tmp-san
	ASAN_OPTIONS=detect_leaks=1 $(B)/run_tests_san $(B)/servo-bc $(B)/test-tmp-san
	bash tests/reliability.sh $(B)

# Fuzz harnesses (fuzz/): each surface replayed under ASan + UBSan with gcc in
# make check (fuzz/corpus/NAME and the reproducers in tests/reliability/), and
# run as libFuzzer campaigns by make fuzz (clang).

$(B)/fuzz/%_replay: fuzz/fuzz_%.c fuzz/replay.c $(FUZZ_COMMON) $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(FUZZ_FLAGS) -Wall -Wextra -Werror -fsanitize=address,undefined -fno-sanitize-recover=all -o $@ \
	  $< fuzz/replay.c fuzz/private_folder.c fuzz/drive_controller.c $(CORE_SRC) $(LDLIBS)

$(B)/fuzz/%_fuzzer: fuzz/fuzz_%.c $(FUZZ_COMMON) $(CORE_SRC) $(CORE_HDR)
	@bash scripts/install-deps.sh fuzz
	@mkdir -p $(@D)
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -o $@ \
	  $< fuzz/private_folder.c fuzz/drive_controller.c $(CORE_SRC) $(LDLIBS)

$(B)/fuzz/restart_seed: fuzz/restart_seed.c fuzz/restart_case.h $(B)/libservo_bc.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

# a valid restart input of this version, beside the committed corpus
$(B)/fuzz/corpus/restart/seed.bin: $(B)/fuzz/restart_seed
	@mkdir -p $(@D)
	$(B)/fuzz/restart_seed $@

fuzz: $(FUZZ_NAMES:%=$(B)/fuzz/%_fuzzer) $(B)/fuzz/corpus/restart/seed.bin
	bash fuzz/campaign.sh $(B)/fuzz $(FUZZ_RUNS) $(FUZZ_NAMES)

# The C suite under valgrind in two halves side by side (about 10 minutes each on
# the CI machine): the suites named here, and all the others.
VALGRIND = valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect -q
VALGRIND_HALF = generate,irregular3d,point,interior,interior-bonds
check-valgrind: $(B)/run_tests $(B)/servo-bc $(B)/servo-bc-plot
	@mkdir -p $(B)/valgrind-a $(B)/valgrind-b
	@SBC_TEST_SUITE=$(VALGRIND_HALF) $(VALGRIND) $(B)/run_tests $(B)/servo-bc $(B)/valgrind-a > $(B)/valgrind-a.log 2>&1 & \
	  half=$$!; SBC_TEST_SKIP=$(VALGRIND_HALF) $(VALGRIND) $(B)/run_tests $(B)/servo-bc $(B)/valgrind-b \
	  > $(B)/valgrind-b.log 2>&1; b=$$?; wait $$half; a=$$?; cat $(B)/valgrind-a.log $(B)/valgrind-b.log; \
	  echo "valgrind: $(VALGRIND_HALF): exit $$a; the other suites: exit $$b"; test $$a = 0 && test $$b = 0

# LAMMPS adapter against the Debian package: build/lmp_servo. The few headers
# Debian's liblammps-dev lacks are shipped in lammps_fix/debian_headers/ (README there).
LMP_HDR = lammps_fix/debian_headers
LMP_DEV = $(B)/lammps-dev.installed
LMP_SRC = lammps_fix/fix_servo_bc.cpp lammps_fix/fix_servo_bc_restart.cpp lammps_fix/fix_servo_bc.h lammps_fix/fix_servo_bc_lammps.h lammps_fix/lmp_servo.cpp \
  lammps_fix/fix_servo_bc_bonds.cpp lammps_fix/fix_servo_bc_bonds_slots.cpp lammps_fix/fix_servo_bc_bonds_contacts.cpp lammps_fix/fix_servo_bc_bonds.h

lammps: $(B)/lmp_servo $(B)/servo_bc_plugin.so

$(LMP_DEV):
	@mkdir -p $(B)
	@bash scripts/install-deps.sh lammps-dev
	@touch $@

$(B)/lmp_servo: $(LMP_SRC) $(B)/libservo_bc.a $(LMP_DEV)
	mpicxx -std=c++11 -O2 -g -DOMPI_SKIP_MPICXX -Wall -Wextra -I/usr/include/lammps -I$(LMP_HDR) \
	  -Isrc_core/include -o $@ lammps_fix/lmp_servo.cpp lammps_fix/fix_servo_bc.cpp lammps_fix/fix_servo_bc_restart.cpp lammps_fix/fix_servo_bc_bonds.cpp lammps_fix/fix_servo_bc_bonds_slots.cpp lammps_fix/fix_servo_bc_bonds_contacts.cpp \
	  $(B)/libservo_bc.a -llammps $(LDLIBS)

# the plugin: for `plugin load` in LAMMPS builds with the PLUGIN package
$(B)/servo_bc_plugin.so: $(LMP_SRC) lammps_fix/plugin.cpp $(B)/libservo_bc.a $(LMP_DEV)
	mpicxx -std=c++11 -O2 -g -fPIC -shared -DOMPI_SKIP_MPICXX -Wall -Wextra -I/usr/include/lammps -I$(LMP_HDR) \
	  -Isrc_core/include -o $@ lammps_fix/plugin.cpp lammps_fix/fix_servo_bc.cpp lammps_fix/fix_servo_bc_restart.cpp lammps_fix/fix_servo_bc_bonds.cpp lammps_fix/fix_servo_bc_bonds_slots.cpp lammps_fix/fix_servo_bc_bonds_contacts.cpp \
	  $(B)/libservo_bc.a $(LDLIBS)

$(B)/plugin_driver: tests/lammps/plugin_driver.cpp $(LMP_DEV)
	mpicxx -std=c++11 -O2 -g -DOMPI_SKIP_MPICXX -Wall -Wextra -I/usr/include/lammps -I$(LMP_HDR) \
	  -o $@ tests/lammps/plugin_driver.cpp -llammps -ldl

check-lammps: $(B)/lmp_servo $(B)/servo-bc $(B)/servo_bc_plugin.so $(B)/plugin_driver
	bash tests/lammps/closed_form.sh $(B)/lmp_servo $(B)/plugin_driver $(B)/servo_bc_plugin.so
	bash tests/lammps/bonds.sh $(B)/lmp_servo
	bash tests/lammps/restart_repro.sh $(B)/lmp_servo
	bash tests/lammps/cubic.sh $(B)/lmp_servo

# LIGGGHTS adapter: the LAMMPS fix source compiled against LIGGGHTS 3.8
# (lammps_fix/fix_servo_bc.cpp with -DSERVO_BC_LIGGGHTS; the differences are in
# liggghts_fix/fix_servo_bc_liggghts.h)
LIG_SRC = lammps_fix/fix_servo_bc.cpp lammps_fix/fix_servo_bc_restart.cpp lammps_fix/fix_servo_bc.h liggghts_fix/fix_servo_bc_liggghts.h \
  liggghts_fix/liggghts_servo.cpp lammps_fix/fix_servo_bc_bonds.cpp lammps_fix/fix_servo_bc_bonds_slots.cpp lammps_fix/fix_servo_bc_bonds_contacts.cpp lammps_fix/fix_servo_bc_bonds.h

liggghts: $(B)/liggghts_servo

/usr/include/liggghts/pair_gran.h:
	@bash scripts/install-deps.sh liggghts-dev

$(B)/liggghts_servo: $(LIG_SRC) $(B)/libservo_bc.a /usr/include/liggghts/pair_gran.h
	mpicxx -std=c++11 -O2 -g -DOMPI_SKIP_MPICXX -DSERVO_BC_LIGGGHTS -Wall -Wextra -isystem /usr/include/liggghts \
	  -Iliggghts_fix -Ilammps_fix -Isrc_core/include -o $@ liggghts_fix/liggghts_servo.cpp lammps_fix/fix_servo_bc.cpp lammps_fix/fix_servo_bc_restart.cpp \
	  lammps_fix/fix_servo_bc_bonds.cpp lammps_fix/fix_servo_bc_bonds_slots.cpp lammps_fix/fix_servo_bc_bonds_contacts.cpp $(B)/libservo_bc.a -lliggghts $(LDLIBS)

check-liggghts: $(B)/liggghts_servo $(B)/servo-bc
	bash tests/liggghts/closed_form.sh $(B)/liggghts_servo $(B)/servo-bc
	bash tests/liggghts/cubic.sh $(B)/liggghts_servo
	bash tests/lammps/bonds.sh $(B)/liggghts_servo liggghts

# every engine on the same case (through the compare command), and the mixed
# layer in LAMMPS and LIGGGHTS against the embedded engine
check-cross-host: $(B)/servo-bc $(B)/servo-bc-plot $(B)/lmp_servo $(B)/liggghts_servo yade
	B=$(abspath $(B)) bash tests/cross_host.sh
	bash tests/mixed_layer.sh $(B)/servo-bc $(B)/lmp_servo $(B)/liggghts_servo
	bash tests/restart_irregular_3d.sh $(B)/servo-bc $(B)/lmp_servo $(B)/liggghts_servo

# make compare CASE=inputs/compare/regular_P_30.sbc: one case on every engine
# there is (hosts that cannot be built or installed are skipped); report in
# out/compare/NAME/ (docs/cross-host.md)
compare: all
	@test -n "$(CASE)" || { echo "usage: make compare CASE=FILE.sbc (cases in inputs/compare/)"; exit 2; }
	@$(MAKE) -k --no-print-directory lammps liggghts yade > $(B)/compare-hosts.log 2>&1 || \
	  echo "compare: not every host could be built or installed (see $(B)/compare-hosts.log)"
	B=$(abspath $(B)) bash scripts/compare.sh $(CASE)

# YADE engine: Python (yade_adapter/servo_bc.py) over the core's shared library
yade: $(B)/libservo_bc.so $(B)/servo-bc
	@bash scripts/install-deps.sh yade

check-yade: yade
	bash tests/yade/run.sh $(B)/libservo_bc.so $(B)/servo-bc

# FE^2 on GetFEM (fe2/, docs/fe2.md), with the Debian interpreter its module is installed for
FE2_PYTHON = /usr/bin/python3
$(B)/fe2-deps.installed:
	@mkdir -p $(B)
	@bash scripts/install-deps.sh fe2
	@touch $@

FE2_TANGENTS ?= condensed affine
fe2-patch: $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot $(B)/fe2-deps.installed
	SERVO_BC_LIB=$(B)/libservo_bc.so $(FE2_PYTHON) fe2/patch.py $(FE2_TANGENTS)
	bash tests/fe2_mpi.sh $(B)/libservo_bc.so $(FE2_PYTHON)
	bash tests/fe2_demo.sh $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot $(FE2_PYTHON)
	bash tests/fe2_irregular.sh $(B)/libservo_bc.so $(B)/servo-bc $(FE2_PYTHON)
	bash tests/fe2_demo3d.sh $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot $(FE2_PYTHON)
	SERVO_BC_LIB=$(B)/libservo_bc.so $(FE2_PYTHON) tests/fe2_femxdem_export.py $(B)/servo-bc $(B)/fe2-femxdem-export

# FE2_DEMO: fe2/biaxial.py's options, e.g. '--elements 4 --n0 100' for the full size (docs/fe2.md)
FE2_DEMO ?=
fe2-demo: $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot $(B)/fe2-deps.installed
	SERVO_BC_LIB=$(B)/libservo_bc.so $(FE2_PYTHON) fe2/biaxial.py --runner $(B)/servo-bc --plot $(B)/servo-bc-plot \
	  --out out/fe2 $(FE2_DEMO)

# FE2_DEMO3D: fe2/triaxial.py's options, e.g. '--elements 2 --n0 60' for the full size, '--only D,P,T,DNS' to try
# (T) points (docs/fe2.md, "The 3D macro model")
FE2_DEMO3D ?=
fe2-demo3d: $(B)/libservo_bc.so $(B)/servo-bc $(B)/servo-bc-plot $(B)/fe2-deps.installed
	SERVO_BC_LIB=$(B)/libservo_bc.so $(FE2_PYTHON) fe2/triaxial.py --runner $(B)/servo-bc --plot $(B)/servo-bc-plot \
	  --out out/fe2 $(FE2_DEMO3D)

# FEMXDEM: the environment fe2/femxdem/run.sh takes, e.g. 'FEMXDEM_STEPS=16' (docs/fe2.md, "FEMxDEM side by side")
FEMXDEM ?=
femxdem: $(B)/libservo_bc.so $(B)/servo-bc-plot $(B)/fe2-deps.installed
	bash scripts/install-deps.sh femxdem
	env SERVO_BC_LIB=$(CURDIR)/$(B)/libservo_bc.so $(FEMXDEM) bash fe2/femxdem/run.sh out/femxdem

$(B)/bench_engine: bench/engine_throughput.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -O3 -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

$(B)/bench_spheres: bench/spheres_throughput.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -O3 -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

$(B)/bench_points: bench/point_batch.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -O3 -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

$(B)/bench_condensed: bench/condensed_solvers.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -O3 -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

$(B)/bench_tangents: bench/tangent_cost.c $(B)/libservo_bc.a
	$(CC) $(CFLAGS) -O3 -o $@ $< $(B)/libservo_bc.a $(LDLIBS)

bench: $(B)/bench_engine $(B)/bench_spheres $(B)/bench_points $(B)/bench_tangents $(B)/bench_condensed
	@bash scripts/install-deps.sh lammps || echo "bench: LAMMPS not available; measuring the embedded engine only"
	bash bench/engine_vs_lammps.sh $(B)/bench_engine
	bash bench/engine_vs_lammps.sh $(B)/bench_spheres 500 3
	bash bench/bpm.sh
	bash bench/bpm_hosts.sh
	bash bench/cohesive_hosts.sh
	$(B)/bench_points 16 10 2
	$(B)/bench_tangents 5 10 20
	$(B)/bench_condensed
	bash bench/newton_servo.sh $(B)/servo-bc
	bash bench/newton_servo.sh $(B)/servo-bc tight
	bash bench/remap_scaling.sh $(B)/servo-bc
	bash bench/interior_scaling.sh $(B)/servo-bc
	DIMENSION=3 bash bench/interior_scaling.sh $(B)/servo-bc
	bash bench/generate_scaling.sh $(B)/servo-bc
	bash bench/generate_scaling.sh $(B)/servo-bc "1000 10000 100000" "1000 10000" pressure
	@$(MAKE) --no-print-directory femxdem FEMXDEM='FEMXDEM_DISCS=400' > $(B)/bench-femxdem.log 2>&1 && \
	  tail -9 $(B)/bench-femxdem.log || echo "bench: FEMxDEM could not be run (see $(B)/bench-femxdem.log)"
	@$(MAKE) --no-print-directory lammps liggghts > $(B)/bench-hosts.log 2>&1 || \
	  { echo "bench: LAMMPS or LIGGGHTS could not be built (see $(B)/bench-hosts.log)"; exit 0; }; \
	  bash bench/lammps_overhead.sh $(B)/lmp_servo && \
	  bash bench/liggghts_overhead.sh $(B)/liggghts_servo $(B)/servo-bc $(B)/lmp_servo $(B)/bench_engine && \
	  bash bench/million.sh $(B)/lmp_servo $(B)/liggghts_servo $(B)/servo-bc && \
	  bash bench/bonds_million.sh && \
	  bash bench/cohesive_million.sh

clean:
	rm -rf $(B) out
