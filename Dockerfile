# lenslab in a container (docs/install.md). The build stage runs the steps a user runs on Debian 12:
# tools/install-deps.sh, the README's configure and build (without the tests), and
# `cmake --install` into /opt/lenslab. That install step, and the installed tree used away from the
# source and build trees (moved, from another folder, as a package for examples/render-frame), are
# what the ctest entry `install` (tests/install/install_test.sh) checks on every test run.
# The runtime stage holds /opt/lenslab and only the libraries lenslab loads (its NEEDED libraries
# plus what it opens at run time: OSMesa, and EGL through libglvnd with Mesa's swrast driver).
#
#   docker build -t lenslab:latest .
#   docker run --rm -v "$PWD:/out" lenslab:latest render --out /out/rows.png
FROM debian:12 AS build
WORKDIR /src
# The dependency script first, so that its layer is reused while the sources change.
COPY tools/install-deps.sh tools/install-deps.sh
RUN bash tools/install-deps.sh && rm -rf /var/lib/apt/lists/*
COPY . .
RUN cmake -S . -B build -G Ninja -DLENSLAB_BUILD_TESTS=OFF \
 && cmake --build build \
 && cmake --install build --prefix /opt/lenslab

FROM debian:12 AS runtime
RUN apt-get update \
 && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
      libopenimageio2.4 libembree3-3 libtbb12 libtinygltf2d libstb0 libglfw3 \
      libosmesa6 libegl1 libegl-mesa0 libgl1-mesa-dri \
 && rm -rf /var/lib/apt/lists/*
# Relocatable: lenslab finds its scenes at /opt/lenslab/share/lenslab relative to its executable.
COPY --from=build /opt/lenslab /opt/lenslab
ENV PATH=/opt/lenslab/bin:$PATH
# Not root; the Kubernetes Job gives its volume to this user's group (fsGroup 1000).
RUN useradd --create-home --uid 1000 --user-group lenslab
USER lenslab
WORKDIR /home/lenslab
ENTRYPOINT ["lenslab"]
CMD ["--help"]
