# cmake -DRUNTIME=<the runtime .so> -DDESTINATION=<dir> -P BundleDependencies.cmake
# Copies the shared libraries the runtime needs that a Linux host cannot be expected to have
# (muparser, pugixml) into DESTINATION, from which the exporter puts them into each FMU next
# to the runtime (its RUNPATH is $ORIGIN). glibc, the GCC runtime libraries and sanitizer
# runtimes are the host's.
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES ${RUNTIME}
  RESOLVED_DEPENDENCIES_VAR resolved
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  POST_EXCLUDE_REGEXES
    "/(ld-linux|libc|libm|libdl|libpthread|librt|libresolv|libmvec)[.-][^/]*$"
    "/(libstdc\\+\\+|libgcc_s|libgomp|libatomic)[.][^/]*$"
    "/lib(asan|ubsan|tsan|lsan|clang_rt)[^/]*$")
if(unresolved)
  message(FATAL_ERROR "the FMU runtime needs libraries not found: ${unresolved}")
endif()
file(REMOVE_RECURSE ${DESTINATION})
file(MAKE_DIRECTORY ${DESTINATION})
foreach(library IN LISTS resolved)
  get_filename_component(name ${library} NAME)
  file(COPY_FILE ${library} ${DESTINATION}/${name})
endforeach()
