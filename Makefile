# Nasaq: `make run` starts the IDE, `make test` runs every suite. Both install what is missing first.
SHELL := /bin/bash
.DEFAULT_GOAL := help

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
PY_STAMP := $(VENV)/.installed
NODE_STAMP := node_modules/.installed
DIST := frontend/dist/index.html
FRONTEND_SOURCES := $(shell find frontend/src frontend/public -type f 2>/dev/null) \
	frontend/index.html frontend/package.json frontend/tsconfig.json frontend/vite.config.ts

.PHONY: help install run test bench conformance fuzz chromium lock clean

help:
	@echo "make run    install what is missing, then serve the IDE at http://127.0.0.1:8000"
	@echo "make test   install what is missing (incl. Chromium), then run every test suite"
	@echo "            (two lanes: pytest | lint, types, vitest, pytest-lang; then Playwright alone)"
	@echo "make bench        STL instructions/s of the CPU; SCL compile lines/s and statements/s;"
	@echo "                  monitoring latency, 100 sessions, block status slowdown;"
	@echo "                  the editor's longest main-thread task with a 500-network STL block"
	@echo "                  and a 5,000-line SCL source, scrolled and monitored (Chromium);"
	@echo "                  a 500-network LAD block opened, scrolled and monitored, and the"
	@echo "                  elkjs layout of a 40-box FBD network in its worker"
	@echo "                  a lesson's Check with a tank in closed loop over 60 s virtual;"
	@echo "                  S7-Graph: a 200-step sequencer's compile time, one call of it against"
	@echo "                  hand-written STL, and the answer time for bad .graph sources"
	@echo "                  and its chart: opened and drawn (< 1 s), monitored while the active"
	@echo "                  step moves (longest main-thread task < 100 ms, Chromium)"
	@echo "make conformance  awlsim's self-checking STL programs (downloads awlsim from PyPI)"
	@echo "make fuzz         the STL, SCL and LAD/FBD compilers fuzzed: 300,000 cases or an hour"
	@echo "                  (FUZZ_CASES, FUZZ_SECONDS, FUZZ_SEED) on every core; each distinct failure"
	@echo "                  printed once, its shrunk reproducer in .fuzz/failures/"
	@echo "                  (make test runs 21,000 cases of it)"
	@echo "make install | make lock (re-pin Python dependencies) | make clean"

install: $(PY_STAMP) $(NODE_STAMP) $(DIST)

$(PY_STAMP): backend/pyproject.toml backend/requirements.lock
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' \
		|| { echo "Nasaq needs Python 3.11 or newer as '$(PYTHON)'"; exit 1; }
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check \
		--constraint backend/requirements.lock --editable 'backend[dev]'
	@touch $@

$(NODE_STAMP): package.json package-lock.json frontend/package.json
	npm ci --no-audit --no-fund
	@touch $@

$(DIST): $(NODE_STAMP) $(FRONTEND_SOURCES)
	npm run build -w frontend
	@touch $@

run: install
	$(BIN)/nasaq serve

test: install chromium
	$(BIN)/python tests/run_suites.py

bench: install chromium
	$(BIN)/python -m nasaq.cpu.bench
	$(BIN)/python -m nasaq.lang.scl.compile_bench
	$(BIN)/python -m nasaq.monitor.bench
	$(BIN)/python tests/bench/lesson_check.py
	npm exec -- playwright test -c tests/e2e/bench/playwright.bench.config.ts
	$(BIN)/python tests/bench/graph_bench.py

# The corpus measurement runs even when awlsim's suite has failures; make fails if either did.
conformance: install
	@status=0; $(BIN)/python tests/conformance/awlsim_suite.py || status=$$?; \
	if [ -n "$$NASAQ_CORPUS" ]; then $(BIN)/python tests/conformance/corpus.py || status=$$?; \
	else echo "Corpus measurement skipped: set NASAQ_CORPUS to a folder gathered with" \
		"tests/conformance/corpus_gather.py (see tests/conformance/README.md)."; fi; \
	exit $$status

FUZZ_CASES ?= 300000
FUZZ_SECONDS ?= 3600
FUZZ_SEED ?= 1
fuzz: install
	$(BIN)/python tests/fuzz/driver.py --cases $(FUZZ_CASES) --seconds $(FUZZ_SECONDS) \
		--seed $(FUZZ_SEED) --out .fuzz/failures

# The browser tests drive Debian's Chromium; Playwright's own browser download is not used.
chromium:
	@if [ ! -x /usr/bin/chromium ]; then \
		echo "Installing Debian's chromium for the browser tests"; \
		sudo=""; [ "$$(id -u)" = 0 ] || sudo=sudo; \
		$$sudo apt-get update -q && \
		DEBIAN_FRONTEND=noninteractive $$sudo apt-get install -y -q chromium; \
	fi

lock:
	$(PYTHON) -m venv /tmp/nasaq-lock && /tmp/nasaq-lock/bin/pip install --quiet pip-tools
	cd backend && { \
		echo "# Pinned versions of every Python dependency of nasaq (runtime, the postgres extra, dev tools)."; \
		echo "# Installed as constraints by \`make install\`; regenerate with \`make lock\`."; \
		/tmp/nasaq-lock/bin/pip-compile --quiet --strip-extras --all-extras --no-header \
			--no-emit-find-links --output-file - pyproject.toml; \
	} > requirements.lock.new && mv requirements.lock.new requirements.lock
	@echo "backend/requirements.lock updated: review the diff, then make install"

clean:
	rm -rf $(VENV) node_modules frontend/node_modules frontend/dist .reports tests/e2e/.output
