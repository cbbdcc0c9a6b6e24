/* fuzz_scene.c - fuzz target: the scene reader (sections, keys with units, includes, references to
 * IES/LDT/SPD/EXR files) on any bytes through lx_scene_read_mem, then the planner on what it accepts.
 * The name puts the scene in samples/scenes so that the seeds' references and includes resolve.
 * Properties: never crash; a parse error names a file; an accepted scene has what its reader promises
 * (rooms, surfaces and obstructions too: reflectances in [0, 1), boxes with volume), and a room's
 * plan stays within its memory bound. Seeds with rooms: tests/fuzz/seeds/scene.
 * Bounded: before planning, the harness coarsens interreflection_tolerance to at least FUZZ_ROOM_TOL,
 * the patches to at least FUZZ_PATCH_M and turns patch_refinement off (the reader has already checked
 * those keys as written, and the planner still sees every other key), so that a room like
 * samples/scenes/office_room.scene plans in a bounded time under the sanitizers: 0.25 s of CPU with
 * ASan+UBSan and coverage, against 2.0 s with the tolerance alone (most of it the near-field direct
 * light on the refined patches near the luminaires) and more than the 10 s timeout at the file's 1e-3. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define FUZZ_ROOM_TOL 5e-2
#define FUZZ_PATCH_M 0.5 /* m: patches no smaller (the planner's own choice, or the file's patch_size) */

int fuzz_scene_one(const uint8_t *data, size_t size)
{
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_scene *sc = NULL;
    lx_status st = lx_scene_read_mem(ctx, "samples/scenes/fuzz.scene", (const char *)data, size, &sc);
    if (st == LX_OK) {
        if (!sc) abort();
        size_t points = 0;
        for (size_t i = 0; i < sc->n_lum; i++) {
            const lx_scene_luminaire *l = &sc->lum[i];
            if (!isfinite(l->pos_m[0]) || !isfinite(l->pos_m[1]) || !isfinite(l->pos_m[2])) abort();
            if (l->kind == LX_SLUM_FILE && !l->lum) abort();
        }
        for (size_t i = 0; i < sc->n_rec; i++) {
            const lx_scene_receiver *r = &sc->rec[i];
            if (r->n < 1 || !r->points) abort();
            for (size_t k = 0; k < 3 * r->n; k++)
                if (!isfinite(r->points[k])) abort();
            points += r->n;
        }
        /* rooms, surfaces, obstructions: what the reader promises */
        for (size_t i = 0; i < sc->n_room; i++)
            for (int k = 0; k < 6; k++)
                if (!(sc->room[i].reflectance[k] >= 0 && sc->room[i].reflectance[k] < 1) ||
                    !(sc->room[i].max_m[k % 3] > sc->room[i].min_m[k % 3]))
                    abort();
        for (size_t i = 0; i < sc->n_surf; i++)
            if (!(sc->surf[i].reflectance >= 0 && sc->surf[i].reflectance < 1)) abort();
        for (size_t i = 0; i < sc->n_obst; i++)
            if (!(sc->obst[i].reflectance >= 0 && sc->obst[i].reflectance < 1)) abort();
        if (points * (sc->n_lum + 1) <= 100000) { /* the planner's near-field test is per pair */
            lx_scene_plan *plan = NULL;
            if (!(sc->interreflection_tol >= FUZZ_ROOM_TOL)) sc->interreflection_tol = FUZZ_ROOM_TOL;
            if (!(sc->patch_size_m >= FUZZ_PATCH_M)) sc->patch_size_m = FUZZ_PATCH_M;
            sc->patch_refinement = 0; /* uniform patches */
            if (lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &plan) == LX_OK) {
                /* interreflection: a mesh within the memory bound, a stopping point that is a number */
                if (plan->on[LX_EFFECT_INTERREFLECTION] &&
                    (!plan->room.mesh || !(plan->room.memory_bytes <= plan->room.memory_limit_bytes) ||
                     !(plan->room.stop_unshot_lm >= 0)))
                    abort();
                if (plan->on[LX_EFFECT_OCCLUSION] && !plan->room.mesh) abort();
                lx_scene_plan_free(plan);
            }
        }
        lx_scene_free(sc);
    } else {
        if (sc) abort(); /* *out stays NULL on failure */
        if (st == LX_EPARSE && !lx_ctx_errfile(ctx)) abort();
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_scene_one(data, size); }
#endif
