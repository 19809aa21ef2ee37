#!/usr/bin/env bash
# Sets NurbsLOD up on Debian bookworm: installs the missing packages, builds into build/,
# installs the workbench into FreeCAD, and runs the main job on the sample model.
#
#   bash scripts/setup.sh                  all four steps
#   bash scripts/setup.sh deps build       only the named steps (deps, build, install, sample)
#
# Safe to run again: it installs only what is missing and rebuilds incrementally (ccache).
# Root is needed only to install packages; as another user it uses sudo for that.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD_DIR="$ROOT/build"

# What the build, the tests and the mesh judge need (DESIGN.md lists what was verified).
PACKAGES=(
    cmake ninja-build g++ ccache pkg-config clang-format
    freecad
    libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
    libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev
    libcoin-dev libopenmesh-dev libglm-dev libeigen3-dev libtbb-dev pybind11-dev
    python3-dev python3-numpy python3-open3d
    libmeshoptimizer-dev libzstd-dev libsqlite3-dev libcli11-dev
    libgtest-dev libgmock-dev libbenchmark-dev libpolyclipping-dev libboost-dev
    xvfb xauth
)

say() { printf '\n== setup: %s\n' "$*"; }

as_root() {
    if [ "$(id -u)" -eq 0 ]; then
        "$@"
    elif command -v sudo >/dev/null; then
        sudo "$@"
    else
        echo "setup: need root (or sudo) to run: $*" >&2
        exit 1
    fi
}

step_deps() {
    local installed missing=() package
    # One query for all: dpkg-query is slow to start.
    installed=$(dpkg-query -W -f='${Package} ${Status}\n' "${PACKAGES[@]}" 2>/dev/null |
        awk '$NF == "installed" && $(NF-1) == "ok" { print $1 }' || true)
    for package in "${PACKAGES[@]}"; do
        grep -qx "$package" <<<"$installed" || missing+=("$package")
    done
    if [ ${#missing[@]} -eq 0 ]; then
        say "all ${#PACKAGES[@]} packages present"
        return
    fi
    say "installing ${missing[*]}"
    # No recommends: the platform facts in DESIGN.md were verified without them, and they
    # would pull in hundreds of megabytes (Qt WebEngine, CalculiX, POV-Ray).
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        "${missing[@]}"
}

step_build() {
    if [ ! -f "$BUILD_DIR/build.ninja" ]; then
        say "configuring $BUILD_DIR"
        cmake -S "$ROOT" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
            -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
    fi
    say "building"
    ninja -C "$BUILD_DIR" -j"$(nproc)"
}

# FreeCAD loads every folder in its user Mod folder; the checkout itself is the workbench.
step_install() {
    local data_dir mod_dir link
    data_dir=$(cd /tmp && freecadcmd -c \
        "import FreeCAD; print('NURBSLOD_DATA_DIR=' + FreeCAD.getUserAppDataDir())" 2>/dev/null |
        sed -n 's/^NURBSLOD_DATA_DIR=//p')
    if [ -z "$data_dir" ]; then
        echo "setup: cannot ask freecadcmd for its user data folder" >&2
        exit 1
    fi
    mod_dir="${data_dir%/}/Mod"
    link="$mod_dir/NurbsLOD"
    mkdir -p "$mod_dir"
    if [ -e "$link" ] && [ ! -L "$link" ]; then
        say "$link is a real folder, not a link: left alone (move it away to install)"
        return
    fi
    ln -sfn "$ROOT" "$link"
    say "workbench installed: $link -> $ROOT"
}

step_sample() {
    local model="$ROOT/out/sample.step"
    mkdir -p "$ROOT/out"
    if [ ! -s "$model" ] || [ "$ROOT/scripts/make_sample_model.py" -nt "$model" ]; then
        say "making the sample model"
        (cd /tmp && NURBSLOD_SAMPLE_OUT="$model" freecadcmd "$ROOT/scripts/make_sample_model.py" |
            grep '^make_sample_model:')
    fi
    say "nurbslod tessellate out/sample.step -o out/sample.obj --relative 1e-3"
    "$BUILD_DIR/App/nurbslod" tessellate "$model" -o "$ROOT/out/sample.obj" --relative 1e-3
}

steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(deps build install sample)
for step in "${steps[@]}"; do
    case "$step" in
        deps | build | install | sample) "step_$step" ;;
        *)
            echo "setup: unknown step '$step' (deps, build, install, sample)" >&2
            exit 2
            ;;
    esac
done
