#!/usr/bin/env bash
# A VTK 9.7.0 tree configured but not built, for the VTK97.CompileModule test
# (docs/VTK97.md): its sources at the tag, from a git clone of VTK (a bare one
# will do), in DIR/src, configured for the rendering modules in DIR/build. The
# configure writes the headers the module needs (module export headers,
# vtkVersionMacros.h, vtk_glad.h, vtkOpenGLError.h, ...) and a build-tree VTK
# package; it needs the GL and X11 headers (libgl-dev, libx11-dev).
#
#   bash scripts/vtk97.sh VTK_GIT_DIR DIR
#
# then configure this project with -DSHADOWMAPS_VTK97_BUILD_DIR=DIR/build.
set -euo pipefail

vtk_git="$1"
dir="$2"
mkdir -p "$dir/src"
# The two largest third-party sources are left out: the configure does not read
# them, and a partial mirror may lack them (git then still names the missing
# object, but writes the rest).
git -C "$vtk_git" archive v9.7.0 -- . \
  ':(exclude)ThirdParty/mpi4py/vtkmpi4py/src/MPI.c' \
  ':(exclude)ThirdParty/sqlite/vtksqlite/sqlite3.c' | tar -x -C "$dir/src"
cmake -S "$dir/src" -B "$dir/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DVTK_BUILD_TESTING=OFF -DVTK_BUILD_EXAMPLES=OFF -DVTK_WRAP_PYTHON=OFF \
  -DVTK_ENABLE_REMOTE_MODULES=OFF \
  -DVTK_GROUP_ENABLE_Imaging=DONT_WANT -DVTK_GROUP_ENABLE_MPI=DONT_WANT \
  -DVTK_GROUP_ENABLE_Qt=DONT_WANT -DVTK_GROUP_ENABLE_Rendering=DONT_WANT \
  -DVTK_GROUP_ENABLE_StandAlone=DONT_WANT -DVTK_GROUP_ENABLE_Views=DONT_WANT \
  -DVTK_GROUP_ENABLE_Web=DONT_WANT \
  -DVTK_MODULE_ENABLE_VTK_RenderingOpenGL2=YES \
  -DVTK_MODULE_ENABLE_VTK_RenderingVolumeOpenGL2=YES
