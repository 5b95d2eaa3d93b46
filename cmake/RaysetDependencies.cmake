# Every dependency comes from Debian 12 packages (scripts/install-deps lists them).
# The order matters: TBB in CONFIG mode and Ceres before OpenVDB, because OpenVDB's
# FindTBB otherwise clashes with TBB's own config.

find_package(GTest REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)

if(RAYSET_CONVERTERS_ONLY)
  return()
endif()

find_package(TBB CONFIG REQUIRED)
find_package(Ceres 2.1 REQUIRED)
list(APPEND CMAKE_MODULE_PATH "/usr/lib/x86_64-linux-gnu/cmake/OpenVDB")
find_package(OpenVDB REQUIRED)
find_package(embree 3 REQUIRED)
# Open MPI: raytrace renders across processes when an MPI launcher starts it.
find_package(MPI REQUIRED COMPONENTS C)
find_package(OpenEXR 3 CONFIG REQUIRED)
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore CommonDataModel FiltersCore FiltersSources FiltersGeneral
  IOXML IOImage RenderingCore RenderingOpenGL2 RenderingFreeType
  InteractionStyle RenderingAnnotation InteractionWidgets)
find_package(benchmark)
