#!/usr/bin/env bash
# The one list of hdprior's dependencies (Debian 12 packages only).
# Installs what is missing with apt-get; a no-op when everything is present.
set -euo pipefail

# What the installed `hdprior` loads by name at run time, besides the shared libraries it links
# (those dpkg-shlibdeps finds): GLFW opens the OpenGL library and Mesa's drivers. CMakeLists.txt
# reads this line into the .deb's Depends; keep it on one line.
runtime_packages=(libgl1 libgl1-mesa-dri)

packages=(
  build-essential cmake pkg-config ninja-build ccache
  libeigen3-dev libpcl-dev libceres-dev libgdal-dev gdal-bin
  libimgui-dev libglfw3-dev libosmesa6-dev libgl-dev libstb-dev
  nlohmann-json3-dev liblz4-dev libzstd-dev
  libgtest-dev libbenchmark-dev libboost-dev libcli11-dev
  xvfb xauth clang libclang-rt-14-dev
  slurmctld slurmd slurm-client munge
  "${runtime_packages[@]}"
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
