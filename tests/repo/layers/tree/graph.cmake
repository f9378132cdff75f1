# A module graph that declares a dep running up the layers (device -> engine/core), as a mistake
# would: the include check must still refuse the include (tests/repo/CMakeLists.txt).
set(PALPATE_MODULES "device;engine/core")
set(PALPATE_LAYERS "base;device;engine;results;report;widgets;app")
set(PALPATE_MODULE_CLOSURE_device "engine/core")
set(PALPATE_MODULE_CLOSURE_engine_core "")
