# What to type to install a missing piece on this machine, for the errors that ask for one: apt-get on
# Debian and Ubuntu (with sudo, unless CMake runs as root: a bare system or a container has no sudo),
# brew on macOS, vcpkg on Windows. scripts/setup.sh says the same of what it cannot install.

# raylab_install_command(OUT DEBIAN HOMEBREW VCPKG): sets OUT to the command that installs the Debian
# package(s) DEBIAN, Homebrew's HOMEBREW or vcpkg's VCPKG (lists), whichever this machine uses.
function(raylab_install_command out debian homebrew vcpkg)
  list(JOIN debian " " debian)
  list(JOIN homebrew " " homebrew)
  list(JOIN vcpkg " " vcpkg)
  if(CMAKE_HOST_WIN32)
    set(command "vcpkg install ${vcpkg}   (then configure with the vcpkg toolchain file, as README.md says)")
  elseif(CMAKE_HOST_APPLE)
    set(command "brew install ${homebrew}")
  else()
    find_program(RAYLAB_APT_GET apt-get)
    mark_as_advanced(RAYLAB_APT_GET)
    if(RAYLAB_APT_GET)
      set(command "apt-get install -y ${debian}")
    else()
      set(command "your distribution's package manager: ${debian} (Debian's names)")
    endif()
    execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(RAYLAB_APT_GET AND NOT uid STREQUAL "0")
      find_program(RAYLAB_SUDO sudo)
      mark_as_advanced(RAYLAB_SUDO)
      if(RAYLAB_SUDO)
        set(command "sudo ${command}")
      else()
        set(command "su root -c '${command}'")
      endif()
    endif()
  endif()
  set(${out} "${command}" PARENT_SCOPE)
endfunction()

# raylab_require_compiler(): a C++ compiler, or an error that says how to install one (CMake's own,
# "No CMAKE_CXX_COMPILER could be found", does not). Before enable_language(CXX).
function(raylab_require_compiler)
  include(CheckLanguage)
  check_language(CXX)
  if(CMAKE_CXX_COMPILER)
    return()
  endif()
  if(CMAKE_HOST_WIN32)
    set(command "Visual Studio 2022 with its \"Desktop development with C++\" workload, then a Developer PowerShell")
  elseif(CMAKE_HOST_APPLE)
    set(command "xcode-select --install")
  else()
    raylab_install_command(command "g++;make" "" "")
  endif()
  unset(CMAKE_CXX_COMPILER CACHE) # looked for again by the next run, after the installation
  message(FATAL_ERROR "raylab needs a C++ compiler, and none was found (CXX, c++, g++, clang++). Install one with\n"
                      "  ${command}\n"
                      "then run the same command again.")
endfunction()
