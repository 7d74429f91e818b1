# poissondisk - one hand-written GNU Makefile: no recursion, no configure.
#
#   make            shared + static library and the CLI, in build/
#   make demo       build, write a maximal pattern to build/demo.txt, print a summary,
#                   draw the gallery in build/gallery/ (make gallery: into docs/)
#   make check      install what the tests need (Debian, as root), then run them all,
#                   and the same suites again under Valgrind memcheck
#   make check-quick  the unit, API, CLI and tools suites (heavy loops shrunk), check-header and
#                   check-layers: no Valgrind, fuzzing, Python, alloc or sanitizers, and
#                   nothing installed; about a minute on an idle machine
#   make bench      benchmark figures against two baselines (not assertions);
#                   make bench-quick: the two smaller sizes only; make bench-phases:
#                   where one run's time goes, stage by stage (PHASES_ARGS='[--threads T] N SEED')
#   make install    PREFIX, DESTDIR, LIBDIR, INCLUDEDIR, BINDIR, MANDIR, PKGCONFIGDIR
#   make install-python   pip-install bindings/python (offline) for SYSTEM_PYTHON
#                   (/usr/bin/python3); make uninstall-python
#   make uninstall, make clean
#   make abi-baseline   regenerate abi/libpoissondisk.abi (only with a map-node bump)
#   make check-threads  4 threads, each with its own handle (and threads of its own,
#                       pds_set_threads), must give the bytes each gives alone on one
#                       thread (built normally; part of make check)
#   make check-sanitizers   not part of make check (slow): check-asan, the unit and API
#                       suites under ASan+UBSan (in build/asan), then check-tsan, the
#                       thread test and the worker_pool and ring_prefetcher unit
#                       suites under ThreadSanitizer (in build/tsan)
#   make fuzz       libFuzzer on the public API for FUZZ_SECONDS (300; clang), crashes in
#                   build/fuzz/; make check replays a fixed walk of 1500 inputs (check-fuzz)

# ---- version: read from the header, the one place it lives -------------------
version_field = $(shell sed -n 's/^\#define PDS_VERSION_$(1) *\([0-9][0-9]*\).*/\1/p' include/poissondisk.h)
MAJOR := $(call version_field,MAJOR)
MINOR := $(call version_field,MINOR)
PATCH := $(call version_field,PATCH)
VERSION := $(MAJOR).$(MINOR).$(PATCH)

# ---- user-settable ---------------------------------------------------------------
PREFIX       ?= /usr/local
EXEC_PREFIX  ?= $(PREFIX)
LIBDIR       ?= $(EXEC_PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
BINDIR       ?= $(EXEC_PREFIX)/bin
MANDIR       ?= $(PREFIX)/share/man
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
DESTDIR      ?=
CFLAGS       ?= -O2 -g
CXXFLAGS     ?= -O3 -g
LDFLAGS      ?=
PYTHON       ?= python3
VALGRIND     ?= valgrind
AR           ?= ar

# ---- mandatory flags: kept apart so user flags cannot drop them ------------------
# -ffp-contract=off: no fused multiply-add behind our back; the predicates'
# error bounds and byte-identical output across compilers depend on it.
# -fno-math-errno: sqrt becomes one instruction (same result, no errno).
PDS_WARN      := -Wall -Wextra -Wshadow -Wconversion -Wno-sign-conversion
PDS_CXXFLAGS  := -std=c++17 -pthread -fPIC -fvisibility=hidden -fvisibility-inlines-hidden \
                 -ffp-contract=off -fno-fast-math -fno-math-errno \
                 -DPDS_BUILDING_LIBRARY -Iinclude -Isrc $(PDS_WARN)
PDS_CFLAGS    := -std=c99 -Iinclude -Wall -Wextra -pedantic
PDS_TEST_CXXFLAGS := -std=c++17 -ffp-contract=off -Iinclude -Isrc $(PDS_WARN)
PDS_TEST_CFLAGS   := $(PDS_CFLAGS) -Wshadow -Wconversion -Wno-sign-conversion
# Each object also writes a .d file naming the headers it includes (-include'd below).
PDS_DEPFLAGS  := -MMD -MP

B := build
SONAME    := libpoissondisk.so.$(MAJOR)
REALNAME  := libpoissondisk.so.$(VERSION)
LIB_SO    := $(B)/$(REALNAME)
LIB_A     := $(B)/libpoissondisk.a
CLI       := $(B)/poissondisk
MAPFILE   := src/libpoissondisk.map

LIB_SRC   := $(sort $(wildcard src/*.cpp src/*/*.cpp))
LIB_OBJ   := $(LIB_SRC:src/%.cpp=$(B)/obj/%.o)
CORE_OBJ  := $(filter-out $(B)/obj/capi%.o,$(LIB_OBJ))

UNIT_SRC  := $(sort $(wildcard tests/unit/*.cpp))
UNIT_BIN  := $(B)/tests/unit
API_SRC   := $(sort $(wildcard tests/api/*.c))
API_BIN   := $(B)/tests/api
EXAMPLE_SRC := $(sort $(wildcard tests/man_examples/*.c))
EXAMPLE_BIN := $(EXAMPLE_SRC:tests/man_examples/%.c=$(B)/examples/%)

# Check framework flags, looked up when a recipe needs them (it may be installed
# by 'make check' itself).
CHECK_LIBS = $$(pkg-config --libs check)

.PHONY: all demo check check-quick bench install uninstall clean deps abi-baseline \
        check-layers check-unit check-api check-header check-symbols check-abi check-man \
        check-examples check-python check-pkgconfig check-cli check-valgrind check-valgrind-unit check-valgrind-api \
        bench-quick bench-phases bench-domains check-bench check-threads check-sanitizers check-asan check-tsan \
        check-tools

all: $(LIB_SO) $(B)/libpoissondisk.so $(B)/$(SONAME) $(LIB_A) $(CLI)

# ---- library -------------------------------------------------------------------------
$(B)/obj/%.o: src/%.cpp include/poissondisk.h Makefile
	@mkdir -p $(@D)
	$(CXX) $(PDS_CXXFLAGS) $(CPPFLAGS) $(CXXFLAGS) $(PDS_DEPFLAGS) -c $< -o $@
-include $(LIB_OBJ:.o=.d)

$(LIB_SO): $(LIB_OBJ) $(MAPFILE)
	$(CXX) -shared -Wl,-soname,$(SONAME) -Wl,--version-script=$(MAPFILE) \
	    -Wl,--no-undefined -Wl,-z,relro -Wl,-z,now $(LDFLAGS) -o $@ $(LIB_OBJ) -lm -pthread

$(B)/$(SONAME): $(LIB_SO)
	ln -sf $(REALNAME) $@
$(B)/libpoissondisk.so: $(B)/$(SONAME)
	ln -sf $(SONAME) $@

$(LIB_A): $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $(LIB_OBJ)

# ---- command-line program: public API only, linked against the static library --------
# The pictures (PNG included: tools/png.c writes it) need nothing beyond libc and libm.
CLI_SRC := tools/poissondisk.c tools/cli_args.c tools/cli_options.c tools/cli_progress.c tools/cli_report.c \
           tools/cli_field.c tools/pgm.c tools/cli_domain.c \
           tools/shape_files.c tools/shape_text.c tools/geojson.c tools/json_check.c \
           tools/cli_sample.c tools/cli_outputs.c tools/cli_output_args.c tools/cli_spectrum.c \
           tools/out_formats.c tools/pattern_svg.c tools/pattern_png.c tools/pattern_domain.c tools/pattern_stats.c tools/pattern_layers.c tools/pattern_kdtree.c \
           tools/png.c tools/points_in.c tools/spectrum.c tools/spectrum_out.c \
           tools/spectrum_plot.c
$(CLI): $(CLI_SRC) $(wildcard tools/*.h) include/poissondisk.h $(LIB_A)
	$(CC) $(PDS_CFLAGS) $(CPPFLAGS) $(CFLAGS) -o $@ $(CLI_SRC) $(LIB_A) $(LDFLAGS) -lstdc++ -lm

# ---- demo: the quick start's first command -------------------------------------------
DEMO_RADIUS ?= 0.002
demo: all demo-gallery
	@$(CLI) --radius $(DEMO_RADIUS) --seed 1 --verify --stats > $(B)/demo.txt
	@echo "points written to $(B)/demo.txt"

# ---- gallery: pictures drawn by the program itself (README "Pictures") ---------------
# demo-gallery writes them to $(B)/gallery (with the spectrum's CSV); make gallery
# copies the pictures over the committed ones in docs/ (about 0.2 MB in all), only
# once all were made. A pattern, its disks on the torus, and the spectrum of 16
# periodic patterns (the paper's figure 6) with its radial curves.
GALLERY := pattern.svg pattern.png disks.svg spectrum.png spectrum_radial.svg
.PHONY: demo-gallery gallery
demo-gallery: $(CLI)
	@mkdir -p $(B)/gallery
	@$(CLI) --radius 0.05 --seed 1 --svg $(B)/gallery/pattern.svg \
	    --png $(B)/gallery/pattern.png --size 256 > /dev/null
	@$(CLI) --periodic --radius 0.05 --seed 3 --svg $(B)/gallery/disks.svg --disks > /dev/null
	@$(CLI) --periodic --radius 0.02 --seed 1 --patterns 16 --spectrum $(B)/gallery/spectrum.png \
	    --size 402 --spectrum-plot $(B)/gallery/spectrum_radial.svg \
	    --spectrum-csv $(B)/gallery/spectrum.csv > /dev/null
	@echo "gallery written to $(B)/gallery: $(GALLERY) spectrum.csv"
gallery: demo-gallery
	@mkdir -p docs
	cp $(addprefix $(B)/gallery/,$(GALLERY)) docs/

# ---- tile-picture: the README's periodic tile, repeated 2x2 (tools/tile_svg.py) ------
# Written to a temporary file first, so a failed run leaves the old picture in place.
.PHONY: tile-picture
tile-picture: $(CLI)
	@mkdir -p docs
	$(CLI) --periodic --radius 0.05 --seed 3 | $(PYTHON) tools/tile_svg.py --radius 0.05 \
	    > docs/periodic_tile.svg.tmp || { rm -f docs/periodic_tile.svg.tmp; exit 1; }
	mv docs/periodic_tile.svg.tmp docs/periodic_tile.svg

# ---- stipple-picture: the README's stippling (section "Variable radius") --------------
# docs/stipple.pgm is a 128 x 128 grey-scale face drawn by docs/stipple_image.py
# (make stipple-image draws it again, the same bytes). --radius-map turns it into
# radii from 0.004 (black) to 0.03 (white); the points are drawn as dots of one size,
# 0.002, so their density shows the picture: docs/stipple.svg, about 4500 points
# and 260 KB. tests/check-cli-field.sh checks that the committed picture is this
# command's output. Written to a temporary file first, as the tile above.
STIPPLE_ARGS := --radius-map docs/stipple.pgm --rmin 0.004 --rmax 0.03 --seed 1 \
                --dot-radius 0.002
.PHONY: stipple-picture stipple-image
stipple-picture: $(CLI)
	$(CLI) $(STIPPLE_ARGS) --verify --stats --svg docs/stipple.svg.tmp > /dev/null \
	    || { rm -f docs/stipple.svg.tmp; exit 1; }
	mv docs/stipple.svg.tmp docs/stipple.svg
stipple-image:
	$(PYTHON) docs/stipple_image.py > docs/stipple.pgm.tmp || { rm -f docs/stipple.pgm.tmp; exit 1; }
	mv docs/stipple.pgm.tmp docs/stipple.pgm

# ---- island-picture: the README's shaped domain (--polygon) ---------------------------
# docs/island.geojson is a made-up island, a coast of 420 vertices with a lake (a hole)
# and an islet, and docs/island.pgm its radius map over the bounding box, dark along
# every shore; docs/island.py draws both (make island-data draws them again, the same
# bytes). The points fill the island and the islet but not the lake, dense along the
# shores: docs/island.svg. tests/check-cli-domains.sh checks that the committed picture
# is this command's output. Written to a temporary file first, as the tile above.
ISLAND_ARGS := --polygon docs/island.geojson --radius-map docs/island.pgm --rmin 0.09 \
               --rmax 0.45 --seed 1 --dot-radius 0.05
.PHONY: island-picture island-data
island-picture: $(CLI)
	$(CLI) $(ISLAND_ARGS) --verify --stats --svg docs/island.svg.tmp > /dev/null \
	    || { rm -f docs/island.svg.tmp; exit 1; }
	mv docs/island.svg.tmp docs/island.svg
island-data:
	$(PYTHON) docs/island.py geojson > docs/island.geojson.tmp \
	    || { rm -f docs/island.geojson.tmp; exit 1; }
	$(PYTHON) docs/island.py pgm > docs/island.pgm.tmp || { rm -f docs/island.pgm.tmp; exit 1; }
	mv docs/island.geojson.tmp docs/island.geojson
	mv docs/island.pgm.tmp docs/island.pgm

# ---- tests ---------------------------------------------------------------------------
deps:
	@sh tests/install-deps.sh

# The longest target, the unit suite under Valgrind, goes first and the API suite
# under Valgrind last: with make -j2 one core runs the first while the other works
# through the rest, and neither waits for long at the end.
check: deps all
	@$(MAKE) --no-print-directory check-valgrind-unit check-header check-layers check-symbols \
	    check-abi check-unit check-api check-threads check-examples check-cli check-tools \
	    check-bench check-python check-pkgconfig check-man check-js check-fuzz check-alloc \
	    check-valgrind-api
	@echo "make check: all checks passed"

# check-quick: what a change is checked with before make check. The Check suites run
# with PDS_TEST_LIGHT=1 (every behaviour, fewer seeds and smaller patterns; the unit
# law tests keep their thresholds); it installs nothing (no deps), so it first
# says plainly when the Check framework is missing instead of failing to link.
check-quick:
	@pkg-config --exists check 2>/dev/null || { echo "make check-quick: the Check unit-test" \
	    "framework is missing (pkg-config check); install it (Debian: apt-get install check," \
	    "or make deps as root)" >&2; exit 1; }
	@$(MAKE) --no-print-directory all $(UNIT_BIN) $(API_BIN)
	@$(MAKE) --no-print-directory check-header check-layers
	PDS_TEST_LIGHT=1 $(UNIT_BIN)
	PDS_TEST_LIGHT=1 $(API_BIN)
	@$(MAKE) --no-print-directory check-cli
	@$(MAKE) --no-print-directory check-tools TOOLS_VALGRIND=no
	@echo "make check-quick: passed (make check runs the full loops and the rest)"

$(UNIT_BIN): $(UNIT_SRC) $(CORE_OBJ) $(wildcard tests/unit/*.hpp)
	@mkdir -p $(@D)
	$(CXX) $(PDS_TEST_CXXFLAGS) $(CXXFLAGS) -o $@ $(UNIT_SRC) $(CORE_OBJ) $(CHECK_LIBS)

$(API_BIN): $(API_SRC) $(wildcard tests/api/*.h) include/poissondisk.h $(LIB_SO) $(B)/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) -o $@ $(API_SRC) -L$(B) -lpoissondisk \
	    -Wl,-rpath,'$$ORIGIN/..' $(CHECK_LIBS) -lm

$(B)/examples/%: tests/man_examples/%.c include/poissondisk.h $(LIB_SO) $(B)/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_CFLAGS) $(CFLAGS) -o $@ $< -L$(B) -lpoissondisk -Wl,-rpath,'$$ORIGIN/..' -lm

check-unit: $(UNIT_BIN)
	$(UNIT_BIN)

check-api: $(API_BIN)
	$(API_BIN)

check-examples: $(EXAMPLE_BIN)
	@for e in $(EXAMPLE_BIN); do echo "$$e"; "$$e" > /dev/null || exit 1; done

check-header:
	@mkdir -p $(B)/tests
	printf '#include <poissondisk.h>\nint main(void){return pds_version_number()==0;}\n' > $(B)/tests/header.c
	$(CC) -std=c99 -pedantic -Werror -Wall -Wextra -Iinclude -c $(B)/tests/header.c -o $(B)/tests/header-c.o
	$(CXX) -x c++ -std=c++11 -pedantic -Werror -Wall -Wextra -Iinclude -c $(B)/tests/header.c -o $(B)/tests/header-cxx.o

check-layers:
	sh tests/check-layers.sh

check-symbols: $(LIB_SO)
	sh tests/check-symbols.sh $(LIB_SO) $(MAPFILE)

check-abi: $(LIB_SO)
	abidiff --no-added-syms --headers-dir2 include --drop-private-types --exported-interfaces-only abi/libpoissondisk.abi $(LIB_SO) || \
	    { echo "ABI differs from abi/libpoissondisk.abi"; exit 1; }

check-man:
	mandoc -T lint -W warning man/*.[0-9]
	sh tests/man_examples/check-pages.sh

check-cli: $(CLI)
	sh tests/check-cli.sh $(CLI)
	sh tests/check-cli-features.sh $(CLI)
	sh tests/check-cli-output.sh $(CLI)
	sh tests/check-cli-field.sh $(CLI)
	sh tests/check-cli-domains.sh $(CLI)
	sh tests/check-cli-threads.sh $(CLI)

# check-python: tests/python/run_venv.py pip-installs a copy of bindings/python offline
# into a scratch venv of SYSTEM_PYTHON (--system-site-packages: Debian's numpy and scipy
# are visible only to /usr/bin/python3) and runs tests/python against the library in
# $(B), through POISSONDISK_LIBRARY; then again with numpy blocked (the list fallback).
SYSTEM_PYTHON ?= /usr/bin/python3
check-python: $(LIB_SO) $(B)/$(SONAME)
	$(SYSTEM_PYTHON) tests/python/run_venv.py $(abspath $(B)/$(SONAME))

check-pkgconfig: all
	sh tests/check-pkgconfig.sh

# check-tools: the program's file readers that need no library (tools/shape_files.h: the
# polygon and fixed-point files) and its --stats line's nearest neighbours, tested on their own from the top of the repository (the
# data is in tests/tools/data/), then under Valgrind when it is installed (CK_FORK=no;
# PDS_TEST_LIGHT=1: 10^5 vertices instead of 10^6) unless TOOLS_VALGRIND=no (check-quick).
TOOLS_TEST_SRC := tests/tools/shape_files_test.c tests/tools/shape_files_bad.c tests/tools/pattern_stats_test.c \
                  tools/shape_files.c tools/shape_text.c tools/geojson.c tools/json_check.c \
                  tools/pattern_stats.c tools/pattern_layers.c tools/pattern_kdtree.c
TOOLS_TEST_BIN := $(B)/tests/shape_files
TOOLS_VALGRIND ?= yes
$(TOOLS_TEST_BIN): $(TOOLS_TEST_SRC) $(wildcard tests/tools/*.h) tools/shape_files.h \
                   tools/shape_files_internal.h tools/pattern_stats.h tools/pattern_kdtree.h
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) -Itools -o $@ $(TOOLS_TEST_SRC) $(CHECK_LIBS) -lm

check-tools: $(TOOLS_TEST_BIN)
	$(TOOLS_TEST_BIN)
	@if [ "$(TOOLS_VALGRIND)" = no ]; then :; \
	elif command -v $(VALGRIND) > /dev/null 2>&1; then \
	    echo "CK_FORK=no PDS_TEST_LIGHT=1 $(VALGRIND) $(VALGRIND_FLAGS) $(TOOLS_TEST_BIN)"; \
	    CK_FORK=no PDS_TEST_LIGHT=1 $(VALGRIND) $(VALGRIND_FLAGS) $(TOOLS_TEST_BIN); \
	else echo "check-tools: $(VALGRIND) not found, the run under Valgrind is skipped"; fi

VALGRIND_FLAGS := --error-exitcode=99 --leak-check=full --show-leak-kinds=all \
                  --errors-for-leak-kinds=all --track-origins=yes -q
check-valgrind: check-valgrind-unit check-valgrind-api
check-valgrind-unit: $(UNIT_BIN)
	CK_FORK=no PDS_TEST_LIGHT=1 $(VALGRIND) $(VALGRIND_FLAGS) $(UNIT_BIN)
check-valgrind-api: $(API_BIN)
	CK_FORK=no PDS_TEST_LIGHT=1 $(VALGRIND) $(VALGRIND_FLAGS) $(API_BIN)

abi-baseline: $(LIB_SO)
	@mkdir -p abi
	abidw --no-corpus-path --headers-dir include --drop-private-types --exported-interfaces-only $(LIB_SO) > abi/libpoissondisk.abi

# ---- threads and sanitizers ------------------------------------------------------------
# check-threads: tests/threads/threads.c (public API only): 4 threads, each with its own
# handle (and threads of its own through pds_set_threads), run a whole script while
# calling the global functions; every thread's results must equal, byte for byte, those
# of the same script run alone on one thread first.
THREADS_BIN := $(B)/tests/threads
$(THREADS_BIN): tests/threads/threads.c include/poissondisk.h $(LIB_SO) $(B)/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) -pthread -o $@ $< -L$(B) -lpoissondisk \
	    -Wl,-rpath,'$$ORIGIN/..' -lm

check-threads: $(THREADS_BIN)
	$(THREADS_BIN)

# check-sanitizers (not part of 'make check': slow) = check-asan + check-tsan. Each
# sanitizer has its own copy of the library objects and shared library, in $(B)/asan
# and $(B)/tsan; the test binaries find theirs through their rpath. Any report fails
# the run: -fno-sanitize-recover and halt_on_error stop at the first one, and in
# Check's fork mode a test whose process exits that way counts as an error (a leak
# too: LeakSanitizer runs as each test's process exits). ASan makes the suites about
# 4 times slower, so Check's per-test timeouts are stretched (its default 4 s is
# too tight). About 4 minutes on 2 cores, build included; PDS_TEST_LIGHT=1 in the
# environment shrinks the heavy loops (about 1 minute).
ASAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
TSAN_FLAGS := -fsanitize=thread
ASAN_ENV   := ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
              CK_TIMEOUT_MULTIPLIER=10
TSAN_ENV   := TSAN_OPTIONS=halt_on_error=1
ASAN_OBJ   := $(LIB_SRC:src/%.cpp=$(B)/asan/obj/%.o)
TSAN_OBJ   := $(LIB_SRC:src/%.cpp=$(B)/tsan/obj/%.o)
SAN_LINK   := -shared -Wl,-soname,$(SONAME) -Wl,--version-script=$(MAPFILE) -Wl,--no-undefined

$(B)/asan/obj/%.o: src/%.cpp include/poissondisk.h Makefile
	@mkdir -p $(@D)
	$(CXX) $(PDS_CXXFLAGS) $(CPPFLAGS) $(CXXFLAGS) $(ASAN_FLAGS) $(PDS_DEPFLAGS) -c $< -o $@
$(B)/tsan/obj/%.o: src/%.cpp include/poissondisk.h Makefile
	@mkdir -p $(@D)
	$(CXX) $(PDS_CXXFLAGS) $(CPPFLAGS) $(CXXFLAGS) $(TSAN_FLAGS) $(PDS_DEPFLAGS) -c $< -o $@
-include $(ASAN_OBJ:.o=.d) $(TSAN_OBJ:.o=.d)

# The shared library and its soname and link-time names, as in $(B).
$(B)/asan/libpoissondisk.so: $(ASAN_OBJ) $(MAPFILE)
	$(CXX) $(SAN_LINK) $(ASAN_FLAGS) $(LDFLAGS) -o $(@D)/$(REALNAME) $(ASAN_OBJ) -lm
	ln -sf $(REALNAME) $(@D)/$(SONAME) && ln -sf $(SONAME) $@
$(B)/tsan/libpoissondisk.so: $(TSAN_OBJ) $(MAPFILE)
	$(CXX) $(SAN_LINK) $(TSAN_FLAGS) $(LDFLAGS) -o $(@D)/$(REALNAME) $(TSAN_OBJ) -lm
	ln -sf $(REALNAME) $(@D)/$(SONAME) && ln -sf $(SONAME) $@

$(B)/asan/tests/unit: $(UNIT_SRC) $(filter-out %/capi%.o,$(ASAN_OBJ)) $(wildcard tests/unit/*.hpp)
	@mkdir -p $(@D)
	$(CXX) $(PDS_TEST_CXXFLAGS) $(CXXFLAGS) $(ASAN_FLAGS) -o $@ $(UNIT_SRC) \
	    $(filter-out %/capi%.o,$(ASAN_OBJ)) $(CHECK_LIBS)
$(B)/asan/tests/api: $(API_SRC) $(wildcard tests/api/*.h) include/poissondisk.h $(B)/asan/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) $(ASAN_FLAGS) -o $@ $(API_SRC) -L$(B)/asan -lpoissondisk \
	    -Wl,-rpath,'$$ORIGIN/..' $(CHECK_LIBS) -lm
$(B)/tsan/tests/unit: $(UNIT_SRC) $(filter-out %/capi%.o,$(TSAN_OBJ)) $(wildcard tests/unit/*.hpp)
	@mkdir -p $(@D)
	$(CXX) $(PDS_TEST_CXXFLAGS) $(CXXFLAGS) $(TSAN_FLAGS) -o $@ $(UNIT_SRC) \
	    $(filter-out %/capi%.o,$(TSAN_OBJ)) $(CHECK_LIBS)
$(B)/tsan/tests/threads: tests/threads/threads.c include/poissondisk.h $(B)/tsan/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) $(TSAN_FLAGS) -pthread -o $@ $< -L$(B)/tsan -lpoissondisk \
	    -Wl,-rpath,'$$ORIGIN/..' -lm

check-asan: $(B)/asan/tests/unit $(B)/asan/tests/api
	$(ASAN_ENV) $(B)/asan/tests/unit
	$(ASAN_ENV) $(B)/asan/tests/api

# The suites whose threads share data: the pool, the helper that walks the
# mesh while the caller inserts, and two threads inserting on two sides.
TSAN_SUITES := worker_pool ring_prefetcher delaunay_sides side_insertions
check-tsan: $(B)/tsan/tests/threads $(B)/tsan/tests/unit
	$(TSAN_ENV) $(B)/tsan/tests/threads
	for suite in $(TSAN_SUITES); do $(TSAN_ENV) CK_RUN_SUITE=$$suite $(B)/tsan/tests/unit || exit 1; done

check-sanitizers: deps
	@$(MAKE) --no-print-directory check-asan
	@$(MAKE) --no-print-directory check-tsan
	@echo "make check-sanitizers: all passed"

# ---- fuzzing: clang + libFuzzer ------------------------------------------------------
# make fuzz runs tests/fuzz/ (see fuzz_api.c) for FUZZ_SECONDS (default 300);
# check-fuzz, part of make check, is the same rule over a fixed walk of 1500 inputs.
# The library is compiled from src/ straight into the fuzz binary, with the mandatory flags plus ASan, UBSan
# and coverage, in $(B)/fuzz/obj. libFuzzer writes new inputs into its first corpus
# directory, so it works on a copy of the seeds in $(B)/fuzz/corpus-work; crashes go
# to $(B)/fuzz/. The memory limits: see "Bounded work" in tests/fuzz/fuzz_ops.c;
# allocator_may_return_null makes an allocation the system refuses PDS_ENOMEM.
FUZZ_CC      ?= clang
FUZZ_CXX     ?= clang++
FUZZ_SECONDS ?= 300
FUZZ_ARGS    ?=
FUZZ_FLAGS   := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined \
                -fno-sanitize-recover=undefined
# Coverage guides the fuzzer through the library too; comparison tracing there would
# cost a third of the time for nothing (the input reaches the library as doubles).
FUZZ_LIB_COV := -fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp
FUZZ_BIN     := $(B)/fuzz/fuzz_api
FUZZ_OBJ     := $(LIB_SRC:src/%.cpp=$(B)/fuzz/obj/%.o)
FUZZ_HOBJ    := $(patsubst tests/fuzz/%.c,$(B)/fuzz/harness/%.o,$(sort $(wildcard tests/fuzz/*.c)))
# -len_control=0: long call sequences from the start (the deeper states matter more
# than the speed short inputs would give).
# make fuzz explores (a new seed each time, FUZZ_SECONDS long); make check's run is a
# fixed walk (seed and number of inputs), so CI's verdict does not depend on luck: the
# same inputs pass or fail on every machine. Crashes make fuzz finds go to the corpus.
FUZZ_LIMIT    = -max_total_time=$(FUZZ_SECONDS)
FUZZ_RUN      = $(FUZZ_LIMIT) -timeout=10 -max_len=512 -len_control=0 \
                -rss_limit_mb=4096 -malloc_limit_mb=4096 -print_final_stats=1 \
                -artifact_prefix=$(B)/fuzz/
.PHONY: fuzz check-fuzz

$(B)/fuzz/obj/%.o: src/%.cpp include/poissondisk.h Makefile
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(PDS_CXXFLAGS) $(FUZZ_FLAGS) $(FUZZ_LIB_COV) $(PDS_DEPFLAGS) -c $< -o $@
$(B)/fuzz/harness/%.o: tests/fuzz/%.c include/poissondisk.h Makefile
	@mkdir -p $(@D)
	$(FUZZ_CC) $(PDS_TEST_CFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link $(PDS_DEPFLAGS) -c $< -o $@
-include $(FUZZ_OBJ:.o=.d) $(FUZZ_HOBJ:.o=.d)

$(FUZZ_BIN): $(FUZZ_HOBJ) $(FUZZ_OBJ)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $^ -lm

check-fuzz: FUZZ_LIMIT = -seed=20261127 -runs=1500
fuzz check-fuzz: $(FUZZ_BIN)
	@rm -rf $(B)/fuzz/corpus-work
	@mkdir -p $(B)/fuzz/corpus-work
	cp tests/fuzz/corpus/* $(B)/fuzz/corpus-work/
	ASAN_OPTIONS=allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    $(FUZZ_BIN) $(FUZZ_RUN) $(FUZZ_ARGS) $(B)/fuzz/corpus-work

# ---- allocation failures ---------------------------------------------------------------
# check-alloc: tests/alloc/ (public API only) replaces malloc and friends in the test
# program (-rdynamic, so the library and libstdc++ bind to them), fails each allocation
# of a fixed call sequence in turn and checks PDS_ENOMEM, no leak, and the same final
# points. Never under Valgrind (it replaces the allocator). PDS_ALLOC_ALL=1: every one.
ALLOC_BIN := $(B)/tests/alloc_fail
$(ALLOC_BIN): $(wildcard tests/alloc/*.c tests/alloc/*.h) include/poissondisk.h $(LIB_SO) $(B)/libpoissondisk.so
	@mkdir -p $(@D)
	$(CC) $(PDS_TEST_CFLAGS) $(CFLAGS) -rdynamic -o $@ $(wildcard tests/alloc/*.c) -L$(B) \
	    -lpoissondisk -Wl,-rpath,'$$ORIGIN/..' -lm
.PHONY: check-alloc
check-alloc: $(ALLOC_BIN)
	$(ALLOC_BIN) small
	$(ALLOC_BIN) torus
	$(ALLOC_BIN) polygon
	$(ALLOC_BIN) mask
	$(ALLOC_BIN) field
	$(ALLOC_BIN) threads
	$(ALLOC_BIN) polygon-threads
	$(ALLOC_BIN) torus-threads
	$(ALLOC_BIN) fixed-threads
	$(ALLOC_BIN) fixed-large
	$(ALLOC_BIN) fixed-one-thread
	$(ALLOC_BIN) fixed-large-one-thread
	$(ALLOC_BIN) field-threads
	$(ALLOC_BIN) field-torus-threads
	$(ALLOC_BIN)

# ---- benchmark -----------------------------------------------------------------------
# The library against two baselines (Bridson, grid dart throwing) at 10^4..10^7
# points: a table on stdout, $(B)/bench.csv and $(B)/bench.svg (the paper's
# figure 7). Then the chunked section (bench/chunked.c): one pds_run against
# pds_run(s, 1) and pds_step loops, same seed, at 10^5 points (--chunked N).
# A few minutes; bench-quick does 10^4 and 10^5 only. BENCH_ARGS adds
# options, e.g. BENCH_ARGS='--repeats 5' (see ./build/bench --help).
BENCH_SRC := $(sort $(wildcard bench/*.c))
$(B)/bench: $(BENCH_SRC) $(wildcard bench/*.h) include/poissondisk.h $(LIB_A)
	$(CC) $(PDS_CFLAGS) -O2 $(CFLAGS) -o $@ $(BENCH_SRC) $(LIB_A) -lstdc++ -lm

bench: $(B)/bench $(B)/bench-domains
	$(B)/bench --csv $(B)/bench.csv --svg $(B)/bench.svg $(BENCH_ARGS)
	$(B)/bench-domains

# A polygonal domain's cost per point against its bounding rectangle
# (bench/domains/domains.c): outlines of 10^3 and 10^5 vertices with a hole and a comb,
# about 10^6 points each, and the verification of one run of each. DOMAINS_ARGS:
# [--repeats K] [--points N] [--threads T] (the parallel process on T threads).
$(B)/bench-domains: bench/domains/domains.c include/poissondisk.h $(LIB_A)
	$(CC) $(PDS_CFLAGS) -O2 $(CFLAGS) -o $@ bench/domains/domains.c $(LIB_A) -lstdc++ -lm

bench-domains: $(B)/bench-domains
	$(B)/bench-domains $(DOMAINS_ARGS)

# Where the time of one run goes (bench/phases.cpp): the stages of a pds_run
# timed one by one, with the darts thrown and the Jones loop's selections.
# PHASES_ARGS: [--threads N] [N [SEED]], default 10^6 points, seed 1; --threads N
# times the parallel process (pds_set_threads) instead of the default one.
PHASES_BIN := $(B)/bench-phases
$(PHASES_BIN): bench/phases.cpp include/poissondisk.h $(LIB_A)
	$(CXX) -std=c++17 -Iinclude -Isrc $(PDS_WARN) -O2 $(CXXFLAGS) -o $@ bench/phases.cpp $(LIB_A) -lm -pthread

bench-phases: $(PHASES_BIN)
	$(PHASES_BIN) $(PHASES_ARGS)

bench-quick: $(B)/bench
	$(B)/bench --csv $(B)/bench-quick.csv --svg $(B)/bench-quick.svg $(BENCH_ARGS) 10000 100000

check-bench: $(B)/bench $(PHASES_BIN)
	sh tests/check-bench.sh $(B)/bench $(PHASES_BIN)

# ---- install -------------------------------------------------------------------------
install: all
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(BINDIR) \
	    $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man3
	install -m 755 $(LIB_SO) $(DESTDIR)$(LIBDIR)/$(REALNAME)
	ln -sf $(REALNAME) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libpoissondisk.so
	install -m 644 $(LIB_A) $(DESTDIR)$(LIBDIR)/libpoissondisk.a
	install -m 644 include/poissondisk.h $(DESTDIR)$(INCLUDEDIR)/poissondisk.h
	# The .pc file is written here, so it names the directories of this install.
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' \
	    -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|g' -e 's|@VERSION@|$(VERSION)|g' \
	    pkgconfig/poissondisk.pc.in > $(DESTDIR)$(PKGCONFIGDIR)/poissondisk.pc
	chmod 644 $(DESTDIR)$(PKGCONFIGDIR)/poissondisk.pc
	install -m 755 $(CLI) $(DESTDIR)$(BINDIR)/poissondisk
	install -m 644 man/*.1 $(DESTDIR)$(MANDIR)/man1/
	install -m 644 man/*.3 $(DESTDIR)$(MANDIR)/man3/
	while read -r name page; do ln -sf "$$page" "$(DESTDIR)$(MANDIR)/man3/$$name"; done < man/links.txt

# install-python: pip-installs the package for SYSTEM_PYTHON, offline (no index, no build
# isolation: Debian's python3-setuptools builds it), from a copy in $(B)/python, as pip
# builds in the source directory. Debian's python3 is externally managed (PEP 668); with
# --break-system-packages pip puts it in /usr/local/lib/python3.X/dist-packages, the
# directory Debian leaves to local installs (PIP_FLAGS to change). DESTDIR stages it.
# The package loads libpoissondisk.so.1: make install first.
PIP_FLAGS ?= --break-system-packages --root-user-action=ignore
.PHONY: install-python uninstall-python
install-python:
	rm -rf $(B)/python && mkdir -p $(B) && cp -R bindings/python $(B)/python
	$(SYSTEM_PYTHON) -m pip install --no-index --no-build-isolation --no-deps \
	    --disable-pip-version-check $(PIP_FLAGS) $(if $(DESTDIR),--root $(DESTDIR)) $(B)/python

uninstall-python:
	$(SYSTEM_PYTHON) -m pip uninstall -y --disable-pip-version-check $(PIP_FLAGS) poissondisk

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/$(REALNAME) $(DESTDIR)$(LIBDIR)/$(SONAME) \
	    $(DESTDIR)$(LIBDIR)/libpoissondisk.so $(DESTDIR)$(LIBDIR)/libpoissondisk.a \
	    $(DESTDIR)$(INCLUDEDIR)/poissondisk.h $(DESTDIR)$(PKGCONFIGDIR)/poissondisk.pc \
	    $(DESTDIR)$(BINDIR)/poissondisk
	for f in man/*.1; do rm -f $(DESTDIR)$(MANDIR)/man1/$${f#man/}; done
	for f in man/*.3; do rm -f $(DESTDIR)$(MANDIR)/man3/$${f#man/}; done
	while read -r name page; do rm -f "$(DESTDIR)$(MANDIR)/man3/$$name"; done < man/links.txt

# ---- make js: the library as WebAssembly, in the npm package bindings/js ------------
# Debian's clang, wasm-ld, wasi-libc and wasm32 libc++ (tests/install-deps.sh). Their
# libc++abi has no exception support, so bindings/js/wasm/cxx_eh.cpp supplies the
# runtime for clang's -fwasm-exceptions code (the engine unwinds). The mandatory flags
# are the native build's (-fPIC aside): the points are the same, byte for byte. The
# 1 MiB stack comes first in memory, so an overflow traps instead of overwriting data.
WASM_CXX    ?= clang++
WASM_CC     ?= clang
WASM_OPT    ?= -O3
WASM_TARGET := --target=wasm32-wasi -fwasm-exceptions
WASM_B      := $(B)/wasm
WASM_OBJ    := $(LIB_SRC:src/%.cpp=$(WASM_B)/obj/%.o) $(WASM_B)/obj/cxx_eh.o $(WASM_B)/obj/glue.o
WASM_OUT    := bindings/js/poissondisk.wasm
comma := ,
WASM_EXPORTS := $(shell sed -n 's/^ *\(pds_[a-z0-9_]*\);.*/\1/p' $(MAPFILE)) malloc free
.PHONY: js check-js
js: $(WASM_OUT)
$(WASM_B)/obj/%.o: src/%.cpp
	@mkdir -p $(dir $@)
	$(WASM_CXX) $(WASM_TARGET) $(WASM_OPT) $(filter-out -fPIC,$(PDS_CXXFLAGS)) $(PDS_DEPFLAGS) -c $< -o $@
$(WASM_B)/obj/cxx_eh.o: bindings/js/wasm/cxx_eh.cpp
	@mkdir -p $(dir $@)
	$(WASM_CXX) $(WASM_TARGET) $(WASM_OPT) -std=c++17 $(PDS_WARN) -c $< -o $@
$(WASM_B)/obj/glue.o: bindings/js/wasm/glue.c include/poissondisk.h
	@mkdir -p $(dir $@)
	$(WASM_CC) $(WASM_TARGET) $(WASM_OPT) $(PDS_CFLAGS) -c $< -o $@
$(WASM_OUT): $(WASM_OBJ)
	$(WASM_CXX) $(WASM_TARGET) $(WASM_OPT) -mexec-model=reactor -fuse-ld=lld -o $@ $(WASM_OBJ) \
	    -Wl,--strip-debug,--max-memory=4294967296,--stack-first,-z,stack-size=1048576 $(addprefix -Wl$(comma)--export=,$(WASM_EXPORTS))
-include $(WASM_OBJ:.o=.d)
# The exception runtime's own cases (bindings/js/test/eh.test.js runs them).
WASM_EH_TEST := $(WASM_B)/eh_cases.wasm
$(WASM_EH_TEST): bindings/js/wasm/test/eh_cases.cpp $(WASM_B)/obj/cxx_eh.o
	$(WASM_CXX) $(WASM_TARGET) $(WASM_OPT) -std=c++17 $(PDS_WARN) -mexec-model=reactor -fuse-ld=lld \
	    -o $@ $< $(WASM_B)/obj/cxx_eh.o -Wl,--max-memory=4294967296

# check-js: the package's Node tests (npm test), then the demo page in headless
# Debian chromium driven by puppeteer-core (npm install fetches it, a dev dependency).
check-js: $(WASM_OUT) $(WASM_EH_TEST) $(CLI)
	cd bindings/js && npm install --no-audit --no-fund --loglevel=error
	cd bindings/js && npm test
	cd bindings/js && npm run test:browser

clean:
	rm -rf $(B) $(WASM_OUT)
