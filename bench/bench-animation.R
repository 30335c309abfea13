# A GIF (and an MP4, where ffmpeg is installed) of one grasp with
# write_hand_animation(), beside the way it was drawn before: a ggplot of
# the same solid hand built and drawn per frame (what gganimate did, 28 s for
# a GIF of one grasp on a loaded 2-core machine, 16 s CPU-bound quiet, of
# which 7 s building and drawing plots and 4.5 s ImageMagick quantising each
# frame again as it wrote the GIF). Steps of the new path are timed apart:
# forward kinematics and polygons, drawing the PNG frames, assembling.
#
#   Rscript bench/bench-animation.R
#   BENCH_QUICK=1 Rscript bench/bench-animation.R
source("bench/_common.R")

reps <- bq(3L, 1L)
max_frames <- bq(150L, 10L)
size <- bq(480L, 160L)
g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
frames <- video_timing(g$meta$n_frames, g$rate, max_frames, "gif")$frames
cat(sprintf("one grasp (%s): %d recorded frames at %g Hz -> a GIF of %d frames, %d x %d pixels\n",
            g$meta$grasp, g$meta$n_frames, g$rate, frames, size, size))

timed <- function(expr) {
  st <- system.time(expr)
  c(elapsed = st[["elapsed"]], cpu = cpu_of(st))
}
best <- function(f) {
  t <- vapply(seq_len(reps), function(i) f(), numeric(2))
  t[, which.min(t["elapsed", ])]
}
dir <- tempfile("bench-animation")
dir.create(dir)

gif <- best(function() timed(write_hand_animation(g, file.path(dir, "hand.gif"), max_frames = max_frames,
                                                  width = size, height = size, overwrite = TRUE)))

# the steps, once
geo <- hand_geometry()
at <- round(seq(1, g$meta$n_frames, length.out = frames))
t_poly <- timed({
  pos <- forward_kinematics(g$recordings[[1]], frames = at)[, geo$joints, , drop = FALSE]
  sp <- solid_polygons(project_array(pos, "oblique"), geo)
})
t_draw <- timed({
  grDevices::png(file.path(dir, "f%04d.png"), width = size, height = size, res = 72, type = png_type())
  draw_hand_frames(sp, seq_len(frames), frames, rep("title", frames), rep("subtitle", frames), NULL, size, size)
  grDevices::dev.off()
})

# the reference: a ggplot of the same hand built and drawn for every frame
pose <- hand_pose(g, frame = at)
ref <- best(function() timed({
  grDevices::png(file.path(dir, "r%04d.png"), width = size, height = size, res = 72, type = png_type())
  for (f in at) print(ggplot2::autoplot(structure(pose[pose$frame == f, ], class = class(pose),
                                                  skeleton = hand_skeleton())))
  grDevices::dev.off()
}))

mp4 <- if (nzchar(Sys.which("ffmpeg"))) {
  best(function() timed(write_hand_animation(g, file.path(dir, "hand.mp4"), max_frames = max_frames,
                                            width = size, height = size, overwrite = TRUE)))
}

cat(sprintf("GIF, write_hand_animation():        %6.2f s elapsed, %6.2f s CPU (best of %d)\n",
            gif[["elapsed"]], gif[["cpu"]], reps))
cat(sprintf("  forward kinematics + polygons:    %6.2f s\n", t_poly[["elapsed"]]))
cat(sprintf("  drawing %3d PNG frames (grid):    %6.2f s\n", frames, t_draw[["elapsed"]]))
cat(sprintf("  assembling the GIF (the rest):    %6.2f s\n",
            max(0, gif[["elapsed"]] - t_poly[["elapsed"]] - t_draw[["elapsed"]])))
cat(sprintf("reference, a ggplot per frame (drawing only, no GIF): %6.2f s elapsed, %6.2f s CPU\n",
            ref[["elapsed"]], ref[["cpu"]]))
cat(sprintf("ratio reference / new GIF (CPU): %.1fx\n", ref[["cpu"]] / gif[["cpu"]]))
if (!is.null(mp4)) {
  cat(sprintf("MP4, write_hand_animation():        %6.2f s elapsed, %6.2f s CPU in R (ffmpeg not counted)\n",
              mp4[["elapsed"]], mp4[["cpu"]]))
}
cat(sprintf("target: a GIF of one grasp in 3 s or less on 2 cores: %s\n",
            if (gif[["elapsed"]] <= 3) "met" else "not met (see the load average above)"))

bench_record("gif_one_grasp_elapsed", gif[["elapsed"]], "s")
bench_record("gif_one_grasp_cpu", gif[["cpu"]], "s")
bench_record("gif_frames_drawn_per_s", frames / t_draw[["elapsed"]], "frames/s")
bench_record("ggplot_per_frame_over_gif_cpu", ref[["cpu"]] / gif[["cpu"]], "x")
if (!is.null(mp4)) bench_record("mp4_one_grasp_elapsed", mp4[["elapsed"]], "s")
unlink(dir, recursive = TRUE)
