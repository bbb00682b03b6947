# ugo — the two commands of the README: `make demo` and `make test`.
# Both install what the build needs on a fresh Debian machine (the HDF5 C library).

CARGO ?= cargo
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
DEMO_CASE ?= cases/cornell-box.toml
DEMO_OUT ?= out/cornell-box.h5

.PHONY: all deps build demo test clean

all: build

# The HDF5 C library, found through pkg-config; installed with apt-get when missing.
deps:
	@pkg-config --exists hdf5 2>/dev/null || pkg-config --exists hdf5-serial 2>/dev/null || { \
	  echo "ugo: installing the HDF5 C library (libhdf5-dev) with apt-get"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq libhdf5-dev pkg-config hdf5-tools >/dev/null; }

build: deps
	$(CARGO) build --release

demo: build
	mkdir -p out
	./target/release/ugo info $(DEMO_CASE)
	./target/release/ugo solve $(DEMO_CASE) -o $(DEMO_OUT)
	@command -v h5dump >/dev/null && h5dump -H $(DEMO_OUT) | head -60 || true

test: deps
	$(CARGO) test --release

clean:
	$(CARGO) clean
	rm -rf out
