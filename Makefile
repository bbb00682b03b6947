# ugo — the two commands of the README: `make demo` and `make test`.
# Both install what the build needs on a fresh Debian machine: the HDF5 C library
# (found through pkg-config) and, for the demo's listing, h5dump.

CARGO ?= cargo
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
DEMO_CASE ?= cases/cornell-box.toml
DEMO_OUT ?= out/cornell-box.h5

.PHONY: all deps build demo test clean

all: build

deps:
	@missing=""; \
	pkg-config --exists hdf5 2>/dev/null || missing="$$missing libhdf5-dev"; \
	command -v pkg-config >/dev/null || missing="$$missing pkg-config"; \
	command -v h5dump >/dev/null || missing="$$missing hdf5-tools"; \
	if [ -n "$$missing" ]; then \
	  echo "ugo: installing$$missing with apt-get"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing >/dev/null; \
	fi

build: deps
	$(CARGO) build --release

demo: build
	mkdir -p out
	./target/release/ugo info $(DEMO_CASE)
	./target/release/ugo solve $(DEMO_CASE) -o $(DEMO_OUT)
	h5dump -H $(DEMO_OUT)
	./target/release/ugo render $(DEMO_OUT) -o out --false-colour log --orders 1,8,64

test: deps
	$(CARGO) test --release

clean:
	$(CARGO) clean
	rm -rf out
