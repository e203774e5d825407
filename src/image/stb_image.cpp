// The one compilation of stb_image, the decoder of the image files a scene reads (height fields, image maps).
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
