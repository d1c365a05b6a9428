// Only built where stb comes header-only (Homebrew, vcpkg): Debian's libstb already holds these.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
