/* render/camera.h - the pinhole camera of the book: vertical field of view,
 * look-from, look-at and an up vector.
 *
 * Every chapter of Shirley's "Ray Tracing: The Rest of Your Life" (v1.123)
 * from its chapter 4 on renders the Cornell box through this camera (from (278, 278, -800) at
 * (278, 278, 0), 40 degrees). Image rows count from the top, columns from
 * the left; a point (x, y) of the image plane in pixel units maps to a
 * unit ray direction.
 */
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "mc/vec3.h"
#include "render/ray.h"

/* Where the camera is and what it sees. */
typedef struct rt_camera_params {
    vec3 lookfrom, lookat, vup;
    double vfov_deg; /* vertical field of view in degrees, in (0, 180) */
} rt_camera_params;

/* The camera ready to shoot rays for a width x height image. */
typedef struct rt_camera {
    vec3 origin;
    vec3 corner;      /* the top-left corner of the image on the plane at distance 1 */
    vec3 du, dv;      /* one pixel to the right, one pixel down */
    int width, height;
} rt_camera;

/* The camera for the given parameters and image size (width, height >= 1;
 * lookfrom != lookat; vup not parallel to the view direction). */
rt_camera rt_camera_make(rt_camera_params p, int width, int height);

/* The ray through the image point (x, y) in pixel units: column x in
 * [0, width), row y in [0, height) from the top. Pixel (i, j) covers
 * [i, i + 1) x [j, j + 1). The direction is unit length. */
rt_ray rt_camera_ray(const rt_camera *c, double x, double y);

#endif /* RT_CAMERA_H */
