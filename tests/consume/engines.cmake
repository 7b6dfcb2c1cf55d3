# Included by the find_package and add_subdirectory consumers, after they
# define `app`: where this project finds an engine, spinslide must define its
# spinslide::<engine> target (cmake/spinslideEngines.cmake); `app` then links
# it and checks it (SPINSLIDE_CONSUME_<ENGINE> in ../main.cpp).
find_package(mujoco CONFIG QUIET)
find_package(Bullet CONFIG QUIET CONFIGS BulletConfig-float64.cmake)
find_package(box2d CONFIG QUIET)
foreach(engine mujoco bullet box2d)
  string(TOUPPER "${engine}" ENGINE)
  if((engine STREQUAL "mujoco" AND TARGET mujoco::mujoco) OR
     (engine STREQUAL "bullet" AND BULLET_FOUND) OR (engine STREQUAL "box2d" AND TARGET box2d::box2d))
    if(NOT TARGET spinslide::${engine})
      message(FATAL_ERROR "${engine} is installed, but spinslide defines no spinslide::${engine}")
    endif()
    target_link_libraries(app PRIVATE spinslide::${engine})
    target_compile_definitions(app PRIVATE SPINSLIDE_CONSUME_${ENGINE})
  endif()
endforeach()
