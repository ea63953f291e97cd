# The simulator, its tools and the Python sweep package in one image, for
# Dask workers on Kubernetes or a batch system (docs/GUIDE-sweeps.md).
# Built from Debian 12 as a developer's machine is: `make deps` installs
# the Debian packages and the venv (build/venv), `make tools` builds mmsim.
FROM debian:12
RUN apt-get update && apt-get install -y --no-install-recommends make ca-certificates && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY . /src
RUN make deps && make -j"$(nproc)" tools && rm -rf /var/lib/apt/lists/*
ENV PYTHONPATH=/src/python MMSIM=/src/build/mmsim PATH=/src/build/venv/bin:/src/build:/src/tools:$PATH
# A Dask worker by default; the scheduler's address is its argument.
ENTRYPOINT ["/src/build/venv/bin/python", "-m", "distributed.cli.dask_worker"]
