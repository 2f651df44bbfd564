# AMES -- the Algebraic MEchanics Simulator.
#   make demo   install missing Debian packages, then run the main job: bin/ames on the wedge
#   make test   install missing Debian packages, then run every FiveAM suite
#   make bench  run the benchmarks (they print numbers)

DEBS  = sbcl maxima maxima-share cl-alexandria cl-fiveam cl-ppcre \
        cl-yason cl-trivial-gray-streams libjs-katex
SBCL ?= sbcl
LISP  = $(SBCL) --noinform --non-interactive --no-sysinit --no-userinit

.PHONY: deps demo test bench clean

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

clean:
	rm -rf build
