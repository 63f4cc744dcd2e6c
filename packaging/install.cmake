# What `cmake --install` puts where, and the Debian packages CPack makes of it
# (`cmake --build build --target package`):
#   snaxels      the application, snaxels-cli, the import helper, styles,
#                the default scene, docs, desktop entry, icon and MIME types
#   snaxels-dev  the engine library, its headers and its CMake package
#                (core/CMakeLists.txt installs those)
# Package dependencies of snaxels are computed from the linked libraries
# (dpkg-shlibdeps), plus Qt's platform plugins, which nothing links.

install(TARGETS snaxels-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
if(SNAXELS_BUILD_GUI)
  install(TARGETS snaxels RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
# Both programs look for the helper beside themselves, then in ../libexec/snaxels.
install(TARGETS snaxels-import RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/snaxels COMPONENT runtime)
# The application finds its data in ../share/snaxels, as in the build tree.
install(DIRECTORY resources styles DESTINATION ${CMAKE_INSTALL_DATADIR}/snaxels COMPONENT runtime)
install(FILES README.md DEVELOPING.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
# Debian's place for a package's licence: /usr/share/doc/PACKAGE/copyright.
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright COMPONENT runtime)
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/snaxels-dev RENAME copyright COMPONENT development)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(FILES packaging/snaxels.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications COMPONENT runtime)
install(FILES packaging/snaxels.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
  COMPONENT runtime)
install(FILES packaging/snaxels-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
  RENAME snaxels.xml COMPONENT runtime)

set(CPACK_PACKAGE_NAME snaxels)
set(CPACK_PACKAGE_VENDOR "The snaxels developers")
# The maintainers' address, the one the project's commits are made under.
set(CPACK_PACKAGE_CONTACT "The snaxels maintainers <maintainers@users.noreply.h-seed-10b5db70.example>")
set(CPACK_RESOURCE_FILE_LICENSE "${CMAKE_CURRENT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEB_COMPONENT_INSTALL ON)
# The programs without their debug information (a RelWithDebInfo build's
# is most of their size); CMake never strips the static library.
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME snaxels)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "qt6-qpa-plugins")
# Video and GIF exports run FFmpeg's program.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "ffmpeg")
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "${PROJECT_DESCRIPTION}
 The desktop application (snaxels) and its command-line twin (snaxels-cli)
 find silhouettes, shadow and shading contours, specular gleams and
 parabolic curves on a mesh with snaxels, active contours that travel along
 mesh edges, and draw them with hidden lines and styled fills as SVG, or as
 animated SVG and Lottie in which every contour is one path whose vertices
 move.")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME snaxels-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
# The library is static: a program that links it needs what it links.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libopenmesh-dev, libglm-dev, nlohmann-json3-dev, libassimp-dev, libembree-dev, libpugixml-dev, libpolyclipping-dev, libtbb-dev, librsvg2-dev, libcairo2-dev, libminizip-dev, zlib1g-dev, pkg-config")
set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION "The snaxels engine as a C++ library
 snaxels::core for CMake's find_package(snaxels): mesh import, contour
 finding and tracking, hidden lines, planar maps, styles and SVG export.")
include(CPack)
