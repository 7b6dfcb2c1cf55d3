# The engine adapters' targets (docs/engines.md): spinslide::mujoco,
# spinslide::bullet and spinslide::box2d, each defined only when its engine
# is found.  Used by the
# build tree (CMakeLists.txt) and installed beside spinslideConfig.cmake, so
# that find_package(spinslide) defines them the same way.
#
#   spinslide_engine_targets(<core target> [<engines folder>])
#
# The build tree passes its engines/ folder: each adapter's header is in
# engines/<engine>/include/spinslide/engines/, put on its target's include
# path.  An installed package passes none: the headers are installed beside
# the core's.
#
# spinslide::mujoco links MuJoCo's own mujoco::mujoco (Debian: libmujoco-dev,
# whose CMake package also needs libqhull-dev).  spinslide::bullet links
# Bullet's double-precision libraries (Debian: libbullet-dev ships both;
# BulletConfig-float64.cmake) and defines BT_USE_DOUBLE_PRECISION, as Bullet's
# own package asks; set SPINSLIDE_BULLET_SINGLE to link the float build.
# spinslide::box2d links Box2D's box2d::box2d (Debian: libbox2d-dev).
# Puts engines/<engine>/include on spinslide::<engine>'s include path, where
# an engines folder is given (the build tree).
function(_spinslide_engine_headers engine engines_dir)
  if(engines_dir)
    target_include_directories(spinslide::${engine} INTERFACE "${engines_dir}/${engine}/include")
  endif()
endfunction()

function(spinslide_engine_targets core)
  set(engines_dir "${ARGV1}")
  if(NOT TARGET spinslide::mujoco)
    find_package(mujoco CONFIG QUIET)
    if(TARGET mujoco::mujoco)
      add_library(spinslide::mujoco INTERFACE IMPORTED GLOBAL)
      target_link_libraries(spinslide::mujoco INTERFACE ${core} mujoco::mujoco)
      _spinslide_engine_headers(mujoco "${engines_dir}")
    endif()
  endif()
  if(NOT TARGET spinslide::box2d)
    find_package(box2d CONFIG QUIET)
    if(TARGET box2d::box2d)
      add_library(spinslide::box2d INTERFACE IMPORTED GLOBAL)
      target_link_libraries(spinslide::box2d INTERFACE ${core} box2d::box2d)
      _spinslide_engine_headers(box2d "${engines_dir}")
    endif()
  endif()
  if(NOT TARGET spinslide::bullet)
    if(SPINSLIDE_BULLET_SINGLE)
      find_package(Bullet CONFIG QUIET)
    else()
      find_package(Bullet CONFIG QUIET CONFIGS BulletConfig-float64.cmake)
    endif()
    if(BULLET_FOUND)
      set(libraries "")
      foreach(library BulletDynamics BulletCollision LinearMath)
        if(NOT SPINSLIDE_BULLET_SINGLE)
          set(library "${library}-float64")
        endif()
        find_library(spinslide_${library}_path ${library}
                     HINTS "${BULLET_ROOT_DIR}/${BULLET_LIBRARY_DIRS}")
        if(NOT spinslide_${library}_path)
          return()
        endif()
        list(APPEND libraries "${spinslide_${library}_path}")
      endforeach()
      add_library(spinslide::bullet INTERFACE IMPORTED GLOBAL)
      target_include_directories(spinslide::bullet SYSTEM INTERFACE
                                 "${BULLET_ROOT_DIR}/${BULLET_INCLUDE_DIR}")
      string(REPLACE "-D" "" definitions "${BULLET_DEFINITIONS}")
      target_compile_definitions(spinslide::bullet INTERFACE ${definitions})
      target_link_libraries(spinslide::bullet INTERFACE ${core} ${libraries})
      _spinslide_engine_headers(bullet "${engines_dir}")
    endif()
  endif()
endfunction()
