# Export side of the FMU tests: the checker runs the real `tlmhub-cli fmu` and `tlmhub-cli
# run`, and loads the runtime library from the FMU it wrote.
add_dependencies(tlmhub-fmu-tests tlmhub-fmu-runtime)
# The runtime's resource-location decoding, tested on its own.
target_sources(tlmhub-fmu-tests PRIVATE ${PROJECT_SOURCE_DIR}/fmu/runtime/ResourceLocation.cpp)
