/* Linked into the sanitized VTK tests only. Mesa's libGLX_mesa dlopen()s the OpenGL driver
 * (swrast_dri.so under Xvfb, <gpu>_dri.so on hardware) and dlclose()s it when the X display is
 * closed, before exit. LeakSanitizer then no longer scans the driver's globals, so the blocks that
 * only they point to are reported as leaks whose allocation stack is one frame in an
 * "<unknown module>": a report about Mesa that no suppression can name and that hides nothing of
 * ours. This dlclose() leaves OpenGL drivers (file names ending in "_dri.so") mapped until the
 * process exits, so their memory counts as reachable, as it does for every library still loaded;
 * every other handle goes to the real dlclose() (through ASan's interceptor). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <link.h>
#include <string.h>

int dlclose(void* handle)
{
  static int (*next)(void*) = NULL;
  struct link_map* map = NULL;
  size_t n;
  if (!next)
  {
    next = (int (*)(void*))dlsym(RTLD_NEXT, "dlclose");
  }
  if (handle && dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map && map->l_name)
  {
    n = strlen(map->l_name);
    if (n >= 7 && strcmp(map->l_name + n - 7, "_dri.so") == 0)
    {
      return 0;
    }
  }
  return next ? next(handle) : -1;
}
