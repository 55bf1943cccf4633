# slipfield: `make verify` and `make test` install what is missing, build,
# and run.  See README.md.
SHELL := /bin/sh
CC ?= cc
BUILD := build
# make MPI=1: an MPI build in build-mpi/ (OpenMPI's mpicc); `make mpi-test`
# checks that `mpirun -np 2 ... sweep` gives the serial run's bytes
MPI ?=
ifeq ($(MPI),1)
CC := mpicc
BUILD := build-mpi
MPI_FLAGS := -DSF_MPI
endif
JOBS ?= $(shell nproc 2>/dev/null || echo 1)
TIER ?= quick
CASES ?= $(sort $(wildcard cases/*/*.md))
SEED ?=
VERIFY_FLAGS ?=
# make verify BASELINE=old/results.json: also write reports/drift.md
BASELINE ?=

PKGS := gsl fftw3 jansson
GIT_REV := $(shell git rev-parse --short HEAD 2>/dev/null || echo unknown)
WARN := -Wall -Wextra -Wpedantic -Werror
# -fno-math-errno -fno-trapping-math: nothing reads errno after a libm
# call nor the floating-point exception flags (no <fenv.h>); without them
# sqrt keeps a branch to the library (errno on a negative argument) and a
# select before a sqrt or a division stays a branch (it could trap), and
# the wrench's cell loop does not vectorise (-fopt-info-vec).  Values are
# unchanged: no reassociation, no contraction (-std=c11 keeps
# -ffp-contract=off).
# Layering: solver/ sees only itself, verification/ sees solver/ and
# itself (plus the generated headers), cli/, tests/ and bench/ see
# everything.  Inside solver/, a layer folder (solver/LAYERS, bottom up)
# sees itself and the layers below; the top of solver/ (model.c,
# slipfield.h) sees every layer.  The -I flags are per directory, so an
# upward #include does not compile; scripts/layering.sh (make layering,
# run by make test) also greps for one, with a message that names the rule.
BASE_CFLAGS := -std=c11 -D_POSIX_C_SOURCE=200809L -fno-math-errno -fno-trapping-math $(WARN) -fopenmp $(MPI_FLAGS)
SOLVER_LAYERS := $(shell sed -e 's/\#.*//' solver/LAYERS)
SOLVER_DIRS := solver $(addprefix solver/,$(SOLVER_LAYERS))
# INC_solver/<layer>: that layer's folder and the folders below it
$(foreach i,$(shell seq $(words $(SOLVER_LAYERS))),$(eval \
  INC_solver/$(word $(i),$(SOLVER_LAYERS)) := $(addprefix -Isolver/,$(wordlist 1,$(i),$(SOLVER_LAYERS)))))
INC_solver := $(addprefix -I,$(SOLVER_DIRS))
INC_verification := $(INC_solver) -Iverification -I$(BUILD)/gen
INC_ALL := $(INC_solver) -Iverification -Icli -Itests -I$(BUILD)/gen
# $(call incs,source.c): the -I flags of the source's folder (a solver
# layer), else of its top directory
incs = $(or $(INC_$(patsubst %/,%,$(dir $(1)))),$(INC_$(firstword $(subst /, ,$(1)))),$(INC_ALL))
# The git revision and the CVODE choice live in generated headers, rewritten
# by rules (not at parse time: `make help` writes nothing) and only when
# their content changes, so a commit does not rebuild everything.
GEN_HDRS := $(BUILD)/gen/sf_rev.h $(BUILD)/gen/bench_config.h
OPT ?= -O2 -g
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS = $(shell pkg-config --libs $(PKGS) 2>/dev/null || echo -lgsl -lgslcblas -lfftw3 -ljansson) -lm -fopenmp
# cmark-gfm renders the HTML reports (its table extension has no .pc file)
HTML_CFLAGS = $(shell pkg-config --cflags libcmark-gfm 2>/dev/null)
HTML_LIBS = -lcmark-gfm-extensions $(shell pkg-config --libs libcmark-gfm 2>/dev/null || echo -lcmark-gfm)
CMOCKA_CFLAGS = $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS = $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)
SAN := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all

SOLVER_SRC := $(sort $(foreach d,$(SOLVER_DIRS),$(wildcard $(d)/*.c)))
SOLVER_HDR := $(sort $(foreach d,$(SOLVER_DIRS),$(wildcard $(d)/*.h)))
# what the solver computes: a checksum of its sources, every layer folder,
# in make's sorted (byte) order (the paper tier's realisation cache is
# keyed by it, so a solver change recomputes).  After SOLVER_SRC and
# SOLVER_HDR: := expands now (/dev/null: an empty list reads nothing).
SOLVER_SUM := $(shell cat $(sort $(SOLVER_SRC) $(SOLVER_HDR)) /dev/null | cksum | cut -d' ' -f1)
VERIF_SRC := $(sort $(wildcard verification/*.c verification/checks/*.c verification/oracle/*.c))
CLI_SRC := $(sort $(wildcard cli/*.c))
TEST_SRC := $(sort $(wildcard tests/test_*.c))
BENCH_SRC := $(sort $(wildcard bench/*.c))

# $(call objs,variant,sources)
objs = $(patsubst %.c,$(BUILD)/$(1)/%.o,$(2))

SOLVER_OBJ := $(call objs,rel,$(SOLVER_SRC))
VERIF_OBJ := $(call objs,rel,$(VERIF_SRC))
CLI_OBJ := $(call objs,rel,$(CLI_SRC))
TESTS := $(patsubst tests/%.c,$(BUILD)/rel/tests/%,$(TEST_SRC))
TESTS_SAN := $(patsubst tests/%.c,$(BUILD)/san/tests/%,$(TEST_SRC))

.PHONY: all deps verify test check bench mutants clean help report-test fuzz valgrind catalogue mpi-test install uninstall power layering coverage regressions
.SECONDARY:
.DEFAULT_GOAL := all

help:
	@echo "make verify   install deps if missing, build, run the quick-tier cases (TIER=full: quick and full; TIER=paper: the paper's claims at its scale, reports/paper.md; CASES='cases/field/*')"
	@echo "make regressions  the pinned regression cases of the full tier (seeds that once failed; CI runs them) -> reports/regressions/"
	@echo "make test     install deps if missing, run the CMocka unit tests (plain and under ASan+UBSan) and the CLI, install and report scripts"
	@echo "make check    the same as make test"
	@echo "make layering solver/ includes only solver/ (each layer folder only itself and the layers below, solver/LAYERS), verification/ not cli/ (also run by make test)"
	@echo "make coverage line and branch coverage of solver/ by the unit tests + quick tier (gcov, lcov) -> reports/coverage/"
	@echo "make bench    benchmarks -> reports/bench/report.md"
	@echo "make mutants  seeded defects that the cases must catch"
	@echo "make power    measured power of the statistical cases under their power_alt (R=50 runs each) -> reports/power.md"
	@echo "make fuzz     libFuzzer on the scene parser and case reader (FUZZ_TIME=60 s each; needs clang)"
	@echo "make valgrind a few cases and the CLI under valgrind (errors and leaks fail)"
	@echo "make MPI=1    an MPI build in build-mpi/ (mpirun -np P build-mpi/slipfield sweep ...)"
	@echo "make mpi-test the MPI sweep gives the serial bytes (installs OpenMPI if missing)"
	@echo "make report-test  JUnit XML schema + headless-Chromium test of reports/ (after test and verify)"
	@echo "make install  PREFIX=/usr/local (DESTDIR honoured): libslipfield (.a, .so), headers, slipfield.pc, slipfield, slipfield(1)"
	@echo "make uninstall  remove what make install put there (same PREFIX and DESTDIR)"
	@echo "make verify BASELINE=old/results.json   also list what changed since that run (reports/drift.md)"
	@echo "make deps     install libgsl-dev libfftw3-dev libcmocka-dev gnuplot-nox pkg-config libcmark-gfm(-extensions)-dev when missing"

deps:
	@sh scripts/deps.sh

# The compile rules run after deps so that pkg-config answers.
all: deps
	@$(MAKE) --no-print-directory $(BUILD)/slipfield $(BUILD)/libslipfield.so


# verification/plot-style.gp as a C string
$(BUILD)/gen/plot_style.h: verification/plot-style.gp
	@mkdir -p $(dir $@)
	@{ echo 'static const char sf_plot_style[] ='; sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/    "/' -e 's/$$/\\n"/' $<; echo '    ;'; } > $@.tmp && mv $@.tmp $@
$(BUILD)/rel/verification/result.o $(BUILD)/san/verification/result.o: $(BUILD)/gen/plot_style.h

.PHONY: FORCE
FORCE:
$(BUILD)/gen/sf_rev.h: FORCE
	@sh scripts/gen-header.sh $@ '#define SF_GIT_REV "$(GIT_REV)"' '#define SF_SOLVER_SUM "$(SOLVER_SUM)"'
$(BUILD)/gen/bench_config.h: FORCE
	@sh scripts/gen-header.sh $@ '#define SF_HAVE_CVODE $(if $(CVODE_OK),1,0)'

# every object waits for the generated headers (the .d files then track
# which ones it includes)
$(BUILD)/rel/%.o: %.c | $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(call incs,$<) $(OPT) $(PKG_CFLAGS) $(HTML_CFLAGS) $(CMOCKA_CFLAGS) -MMD -MP -c $< -o $@

# the sanitised build is test-only: its solver carries the allocation
# fault hooks (solver/base/sf_alloc.h; disarmed unless tests/test_faults.c arms them)
$(BUILD)/san/%.o: %.c | $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(call incs,$<) -O1 -g $(SAN) -DSF_FAULT_INJECTION $(PKG_CFLAGS) $(HTML_CFLAGS) $(CMOCKA_CFLAGS) -MMD -MP -c $< -o $@

# solver/ again with the fault hooks, optimised as the library, for the
# plain build of tests/test_faults.c only (the library that is installed
# and runs the cases has none: sf_alloc.h compiles them to malloc)
$(BUILD)/fi/%.o: %.c | $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(call incs,$<) $(OPT) -DSF_FAULT_INJECTION $(PKG_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/fi/libslipfield.a: $(call objs,fi,$(SOLVER_SRC))
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/libslipfield.a: $(SOLVER_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/libsfverify.a: $(VERIF_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/san/libslipfield.a: $(call objs,san,$(SOLVER_SRC))
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/san/libsfverify.a: $(call objs,san,$(VERIF_SRC))
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/slipfield: $(CLI_OBJ) $(BUILD)/libsfverify.a $(BUILD)/libslipfield.a
	$(CC) $(OPT) $^ -o $@ $(HTML_LIBS) $(PKG_LIBS)

$(BUILD)/rel/tests/%: $(BUILD)/rel/tests/%.o $(BUILD)/libsfverify.a $(BUILD)/libslipfield.a
	$(CC) $(OPT) $^ -o $@ $(CMOCKA_LIBS) $(HTML_LIBS) $(PKG_LIBS)

$(BUILD)/san/tests/%: $(BUILD)/san/tests/%.o $(BUILD)/san/libsfverify.a $(BUILD)/san/libslipfield.a
	$(CC) -g $(SAN) $^ -o $@ $(CMOCKA_LIBS) $(HTML_LIBS) $(PKG_LIBS)

$(BUILD)/rel/tests/test_faults: $(BUILD)/rel/tests/test_faults.o $(BUILD)/libsfverify.a $(BUILD)/fi/libslipfield.a
	$(CC) $(OPT) $^ -o $@ $(CMOCKA_LIBS) $(HTML_LIBS) $(PKG_LIBS)

# SUNDIALS CVODE is a benchmark-only peer: compiled in when its header is
# there ($(BUILD)/gen/bench_config.h records the choice, so installing it
# rebuilds the bench).
CVODE_OK := $(shell test -f /usr/include/cvode/cvode.h && echo 1)
CVODE_LIBS := $(if $(CVODE_OK),-lsundials_cvode -lsundials_nvecserial)
$(BUILD)/bench/slipfield-bench: $(call objs,rel,$(BENCH_SRC)) $(BUILD)/libsfverify.a $(BUILD)/libslipfield.a
	@mkdir -p $(dir $@)
	$(CC) $(OPT) $^ -o $@ $(HTML_LIBS) $(CVODE_LIBS) $(PKG_LIBS)

test: deps
	@$(MAKE) --no-print-directory test-run

# the GNU name for the tests
check: test

.PHONY: test-run
test-run: $(TESTS) $(TESTS_SAN) $(BUILD)/slipfield $(BUILD)/libslipfield.so
	@st=0; sh scripts/layering.sh || st=1; \
	 sh scripts/layering-test.sh || st=1; \
	 sh scripts/refs-check.sh || st=1; \
	 sh scripts/mutants-fresh.sh || st=1; \
	 sh scripts/run-tests.sh $(BUILD) $(TESTS) -- $(TESTS_SAN) || st=1; \
	 sh scripts/bad-input.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/isolation.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/budget-test.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/resume-test.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/cli-test.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/results-test.sh $(BUILD)/slipfield || st=1; \
	 sh scripts/drift-test.sh || st=1; \
	 sh scripts/install-test.sh || st=1; \
	 sh scripts/python-test.sh || st=1; \
	 sh scripts/readme-test.sh || st=1; \
	 sh scripts/catalogue.sh $(BUILD)/slipfield $(BUILD)/catalogue.md && \
	 if cmp -s $(BUILD)/catalogue.md cases/README.md; then echo "catalogue: cases/README.md up to date"; \
	 else echo "catalogue: cases/README.md is stale: run make catalogue" >&2; st=1; fi; exit $$st

layering:
	@sh scripts/layering.sh

REPEAT ?=
verify: all
ifneq ($(REPEAT),)
	@sh scripts/false-alarm.sh $(REPEAT) $(TIER) $(JOBS)
else
	@$(BUILD)/slipfield verify --jobs $(JOBS) --tier $(TIER) $(if $(SEED),--seed $(SEED)) $(if $(BASELINE),--baseline $(BASELINE)) $(VERIFY_FLAGS) $(CASES)
endif

# The full tier's pinned regression cases (a seed that once failed, kept
# out of the quick tier for its time): CI runs them after make verify.
PINNED = $(shell grep -lE '^pin_seed *= *true' cases/*/*.md)
REGRESSIONS = $(shell grep -lE '^tier *= *full' $(PINNED) /dev/null)
regressions: all
	@$(BUILD)/slipfield verify --jobs $(JOBS) --tier full --reports reports/regressions $(REGRESSIONS)

# the power of each statistical case against its named alternative
R ?= 50
power: all
	@sh scripts/power.sh $(R) $(TIER) $(JOBS)

# after `make test` and `make verify`: JUnit schema and the browser test
report-test:
	@sh scripts/report-test.sh reports

# make bench also installs the benchmark-only peers when it can (never
# linked into slipfield; their sections are skipped with a note when
# absent).  BENCH_PEERS=0: don't try.  BENCH_SECTIONS='field dynamics': a subset.
BENCH_PEERS ?= 1
BENCH_PEER_PKGS := libsundials-dev python3-openturns python3-scipy r-cran-randomfields
BENCH_SECTIONS ?=
bench: all
	@if [ "$(BENCH_PEERS)" != 0 ]; then sh scripts/deps.sh $(BENCH_PEER_PKGS) || \
	   echo "bench: peers not installed: their sections will say so" >&2; fi
	@$(MAKE) --no-print-directory $(BUILD)/bench/slipfield-bench $(BUILD)/slipfield
	@$(BUILD)/bench/slipfield-bench reports/bench $(BENCH_SECTIONS)

# ---- make coverage ---------------------------------------------------------
# solver/ compiled again with --coverage (-O0: branch counts map to the
# source) in $(BUILD)/cov/, with the allocation fault hooks (sf_alloc.h:
# tests/test_faults.c walks the ENOMEM paths) and one copy of the wrench
# (-DSF_NO_CLONES: the same source without the per-ISA target_clones, of
# which a machine runs one); the unit tests and the CLI link it in place of
# the optimised library; scripts/coverage.sh runs the unit tests, the CLI
# scripts of make test and the quick tier with them, then lcov/genhtml
# write reports/coverage/ and the floor in tests/coverage-floor.txt is
# enforced.  lcov is installed (Debian) only for this target.
COV_FLAGS := -O0 -g --coverage -DSF_NO_CLONES -DSF_FAULT_INJECTION
$(BUILD)/cov/%.o: %.c | $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(call incs,$<) $(COV_FLAGS) $(PKG_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/cov/libslipfield.a: $(call objs,cov,$(SOLVER_SRC))
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/cov/tests/%: $(BUILD)/rel/tests/%.o $(BUILD)/libsfverify.a $(BUILD)/cov/libslipfield.a
	@mkdir -p $(dir $@)
	$(CC) --coverage $^ -o $@ $(CMOCKA_LIBS) $(HTML_LIBS) $(PKG_LIBS)

# -u __gcov_dump: the runner's case processes call it before _exit
# (verification/runner.c: a weak reference, which alone would not pull it
# from libgcov), so the quick tier's counts are kept
$(BUILD)/cov/slipfield: $(CLI_OBJ) $(BUILD)/libsfverify.a $(BUILD)/cov/libslipfield.a
	$(CC) --coverage -Wl,-u,__gcov_dump $^ -o $@ $(HTML_LIBS) $(PKG_LIBS)

TESTS_COV := $(patsubst tests/%.c,$(BUILD)/cov/tests/%,$(TEST_SRC))
coverage: deps
	@sh scripts/deps.sh lcov
	@$(MAKE) --no-print-directory $(TESTS_COV) $(BUILD)/cov/slipfield
	@sh scripts/coverage.sh $(BUILD) $(JOBS) $(TESTS_COV)

mutants: all
	@sh scripts/mutants.sh $(MUTANTS)

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

FUZZ_TIME ?= 60
fuzz: all
	@sh scripts/deps.sh clang
	@sh scripts/fuzz.sh $(FUZZ_TIME)

valgrind: all
	@sh scripts/deps.sh valgrind
	@$(MAKE) --no-print-directory $(BUILD)/rel/tests/test_faults
	@sh scripts/valgrind.sh

catalogue: all
	@sh scripts/catalogue.sh $(BUILD)/slipfield cases/README.md
	@echo "catalogue: cases/README.md"

mpi-test:
	@sh scripts/deps.sh libopenmpi-dev openmpi-bin
	@$(MAKE) --no-print-directory all
	@$(MAKE) --no-print-directory MPI=1 all
	@sh scripts/mpi-test.sh build/slipfield build-mpi/slipfield

# ---- make install / uninstall -------------------------------------------
# The solver library, static (the objects every test and case uses) and
# shared (the same sources compiled again with -fPIC in $(BUILD)/pic/), its
# public headers under include/slipfield/, slipfield.pc, the slipfield
# command and its man page (generated from --help and `help scene`).
PREFIX ?= /usr/local
DESTDIR ?=
BINDIR = $(PREFIX)/bin
LIBDIR = $(PREFIX)/lib
INCLUDEDIR = $(PREFIX)/include
MANDIR = $(PREFIX)/share/man
DATADIR = $(PREFIX)/share/slipfield
PCDIR = $(LIBDIR)/pkgconfig
# MAJOR.MINOR.PATCH from solver/base/sf_version.h (releases are tagged vMAJOR.MINOR.PATCH)
sf_ver = $(shell sed -n 's/^\#define SF_VERSION_$(1) \([0-9]*\)$$/\1/p' solver/base/sf_version.h)
SF_VERSION := $(call sf_ver,MAJOR).$(call sf_ver,MINOR).$(call sf_ver,PATCH)
SO_MAJOR := $(firstword $(subst ., ,$(SF_VERSION)))
SONAME := libslipfield.so.$(SO_MAJOR)
SHLIB := libslipfield.so.$(SF_VERSION)
# (internal: sf_alloc.h, the allocation wrappers of the solver's sources,
# and cof_x512.h, the wrench's AVX-512 look-up).  The headers install flat
# in include/slipfield/ whatever their layer folder: <slipfield/cof.h>.
PRIVATE_HEADERS := solver/base/sf_alloc.h solver/disc/cof_x512.h
PUBLIC_HEADERS := $(filter-out $(PRIVATE_HEADERS),$(SOLVER_HDR))
LIB_PKGS := gsl fftw3
LIB_LIBS = $(shell pkg-config --libs $(LIB_PKGS) 2>/dev/null || echo -lgsl -lgslcblas -lfftw3) -lm -fopenmp

$(BUILD)/pic/%.o: %.c | $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(call incs,$<) $(OPT) -fPIC $(PKG_CFLAGS) -MMD -MP -c $< -o $@

# -z defs: the shared library must not lean on symbols of the harness or CLI
$(BUILD)/$(SHLIB): $(call objs,pic,$(SOLVER_SRC))
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,-z,defs $(OPT) $^ -o $@ $(LIB_LIBS)

# the shared library in build/, under its plain name too: python/slipfield
# loads it from the source tree (PYTHONPATH=python)
$(BUILD)/libslipfield.so: $(BUILD)/$(SHLIB)
	ln -sf $(SHLIB) $@

$(BUILD)/slipfield.1: $(BUILD)/slipfield scripts/man.sh
	sh scripts/man.sh $(BUILD)/slipfield $(SF_VERSION) > $@.tmp && mv $@.tmp $@

.PHONY: install-files
install: all
	@$(MAKE) --no-print-directory install-files

# the Python package, where Debian's python3 looks for PREFIX's packages
PYMINOR := $(shell /usr/bin/python3 -c 'import sys; print(sys.version_info[1])' 2>/dev/null || echo 11)
PYDIR ?= $(PREFIX)/lib/python3.$(PYMINOR)/dist-packages
INSTALL_DIRS = $(BINDIR) $(LIBDIR) $(PCDIR) $(INCLUDEDIR)/slipfield $(MANDIR)/man1 $(DATADIR) $(PYDIR)/slipfield
# the folders this install created (uninstall removes them when empty)
DIRS_MANIFEST = $(DATADIR)/install-dirs
install-files: $(BUILD)/slipfield $(BUILD)/libslipfield.a $(BUILD)/$(SHLIB) $(BUILD)/slipfield.1
	@sh scripts/install-dirs.sh missing "$(DESTDIR)" $(INSTALL_DIRS) > $(BUILD)/install-dirs
	install -d $(addprefix $(DESTDIR),$(INSTALL_DIRS))
	install -m 755 $(BUILD)/slipfield $(DESTDIR)$(BINDIR)/slipfield
	install -m 644 $(BUILD)/libslipfield.a $(DESTDIR)$(LIBDIR)/libslipfield.a
	install -m 755 $(BUILD)/$(SHLIB) $(DESTDIR)$(LIBDIR)/$(SHLIB)
	ln -sf $(SHLIB) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libslipfield.so
	install -m 644 $(PUBLIC_HEADERS) $(DESTDIR)$(INCLUDEDIR)/slipfield/
	install -m 644 $(BUILD)/slipfield.1 $(DESTDIR)$(MANDIR)/man1/slipfield.1
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|' \
	    -e 's|@VERSION@|$(SF_VERSION)|' slipfield.pc.in > $(DESTDIR)$(PCDIR)/slipfield.pc
	chmod 644 $(DESTDIR)$(PCDIR)/slipfield.pc
	install -m 644 python/slipfield/__init__.py $(DESTDIR)$(PYDIR)/slipfield/__init__.py
	printf '# written by make install: the library this package loads\nLIBRARY = "%s"\n' '$(LIBDIR)/$(SONAME)' \
	    > $(DESTDIR)$(PYDIR)/slipfield/_installed.py
	@if [ -s $(BUILD)/install-dirs ] || [ ! -f $(DESTDIR)$(DIRS_MANIFEST) ]; then \
	   install -m 644 $(BUILD)/install-dirs $(DESTDIR)$(DIRS_MANIFEST); fi

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/slipfield $(DESTDIR)$(LIBDIR)/libslipfield.a $(DESTDIR)$(LIBDIR)/$(SHLIB) \
	      $(DESTDIR)$(LIBDIR)/$(SONAME) $(DESTDIR)$(LIBDIR)/libslipfield.so $(DESTDIR)$(PCDIR)/slipfield.pc \
	      $(DESTDIR)$(MANDIR)/man1/slipfield.1 $(addprefix $(DESTDIR)$(INCLUDEDIR)/slipfield/,$(notdir $(PUBLIC_HEADERS))) \
	      $(DESTDIR)$(PYDIR)/slipfield/__init__.py $(DESTDIR)$(PYDIR)/slipfield/_installed.py
	rm -rf $(DESTDIR)$(PYDIR)/slipfield/__pycache__
	@rmdir $(DESTDIR)$(INCLUDEDIR)/slipfield 2>/dev/null || true
	@sh scripts/install-dirs.sh remove "$(DESTDIR)" $(DIRS_MANIFEST)
