# AMES -- the Algebraic MEchanics Simulator.
#   make demo   install missing Debian packages, then run the main job: bin/ames on the wedge
#   make test   install missing Debian packages, then run every FiveAM suite
#   make bench  run the benchmarks (they print numbers)
#   make crosscheck  N random scenarios (default 1000; N=, SEED=, FAMILIES=a,b, JOBS= settable) through AMES and
#               the witness (Siconos) in JOBS parallel shards (default 2; each one warm Lisp,
#               Maxima and Python), counts per family and verdict and the time per scenario
#               printed; disagreements written under witness/disagreements/
#   make fuzz   the nightly-size fuzz: 10,000 whole-path cases and 500 runs with a kill -9 of
#               Maxima, figures printed (FUZZ_FORMS, FUZZ_CRASH_RUNS, FUZZ_SEED size it)

DEBS  = sbcl maxima maxima-share cl-alexandria cl-fiveam cl-ppcre \
        cl-yason cl-trivial-gray-streams libjs-katex python3-siconos
SBCL ?= sbcl
LISP  = $(SBCL) --noinform --non-interactive --no-sysinit --no-userinit

N    ?= 1000
SEED ?= 1
FAMILIES ?=
JOBS ?= 2

.PHONY: deps demo test bench fuzz crosscheck clean

deps:
	@missing=""; for p in $(DEBS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "Installing Debian packages:$$missing"; \
	    apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	  else \
	    echo "Missing Debian packages:$$missing"; \
	    echo "Install them with: sudo apt-get install -y --no-install-recommends$$missing"; exit 1; \
	  fi; \
	fi

demo: deps
	bin/ames run scenarios/particle-on-wedge.lisp

test: deps
	$(LISP) --load t/run.lisp

bench: deps
	$(LISP) --load bench/run.lisp

fuzz: deps
	$(LISP) --load t/fuzz.lisp

crosscheck: deps
	@$(LISP) --eval '(require :asdf)' --eval '(asdf:load-asd (truename "ames.asd"))' \
	  --eval '(asdf:load-system "ames")' >/dev/null
	@dir=build/crosscheck-$(SEED); rm -rf $$dir; mkdir -p $$dir; start=$$(date +%s); \
	export N=$(N) SEED=$(SEED) FAMILIES="$(FAMILIES)" SBCL="$(SBCL)"; \
	if command -v parallel >/dev/null; then \
	  seq 0 $$(($(JOBS) - 1)) | parallel -j $(JOBS) --line-buffer witness/crosscheck-shard {} $(JOBS) $$dir; \
	else echo "(GNU parallel missing: the $(JOBS) shards run one after another)"; \
	  for k in $$(seq 0 $$(($(JOBS) - 1))); do witness/crosscheck-shard $$k $(JOBS) $$dir; done; fi; \
	SUMMARY=$$dir SEED=$(SEED) $(LISP) --load t/crosscheck.lisp; status=$$?; \
	echo "  wall time: $$(( $$(date +%s) - start )) s on $(JOBS) processes"; exit $$status

clean:
	rm -rf build
