# The synthesis venv's sitecustomize.py (scripts/install-tools.sh --synth
# copies it into .tools/venv): every YoWASP tool run from the venv gets a
# 2 MiB WebAssembly call stack instead of wasmtime's default 512 KiB.
# Yosys' ABC9 in its sequential mode (`synth_ice40 -dff`) recursed deeper
# than 512 KiB on the slave and the run ended in "wasm trap: call stack
# exhausted" (issue 21). 2 MiB is the most wasmtime allows without a
# larger async stack, which its Python API does not set; the thread the
# YoWASP runtime runs a tool on has the platform's default stack (8 MiB
# on Linux), which holds it.
try:
    import wasmtime
except ImportError:  # the venv before its packages are installed
    wasmtime = None

if wasmtime is not None:
    _config_init = wasmtime.Config.__init__

    def _config_with_stack(self, *args, **kwargs):
        _config_init(self, *args, **kwargs)
        self.max_wasm_stack = 2 * 1024 * 1024

    wasmtime.Config.__init__ = _config_with_stack
