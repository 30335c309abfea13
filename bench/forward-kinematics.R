# Benchmark of forward_kinematics(): the hand-over reconstruction poses
# ~10,000 frames at a time, so the goal is about 1 ms per 100 frames.
# Compares the vectorised computation with posing frame by frame.
# Run from the package root: Rscript bench/forward-kinematics.R (BENCH_QUICK=1: seconds)
source("bench/_common.R")
skel <- hand_skeleton()
set.seed(1)
make <- function(n) matrix(runif(n * 16, -10, 90), n, 16, dimnames = list(NULL, hust_dofs$name))
res <- lapply(bq(c(100, 1000, 10000), c(100, 1000)), function(n) {
  x <- make(n)
  b <- bench::mark(forward_kinematics(x, skel), iterations = bq(15, 3), check = FALSE, filter_gc = FALSE)
  data.frame(frames = n, median_ms = as.numeric(b$median) * 1000, min_ms = as.numeric(b$min) * 1000,
             ms_per_100_frames = as.numeric(b$median) * 1000 / (n / 100))
})
res <- do.call(rbind, res)
print(res, digits = 3)
bench_record(sprintf("%d frames, per 100 frames", max(res$frames)), res$ms_per_100_frames[nrow(res)], "ms")

x <- make(200)
loop <- bench::mark(for (i in seq_len(nrow(x))) forward_kinematics(x[i, , drop = FALSE], skel),
                    iterations = bq(3, 1), check = FALSE)
vec <- bench::mark(forward_kinematics(x, skel), iterations = 15, check = FALSE)
cat(sprintf("200 frames: frame-by-frame %.1f ms, vectorised %.2f ms, speed-up x%.0f\n",
            as.numeric(loop$median) * 1000, as.numeric(vec$median) * 1000,
            as.numeric(loop$median) / as.numeric(vec$median)))
bench_record("200 frames, frame-by-frame / vectorised", as.numeric(loop$median) / as.numeric(vec$median), "x")

# GraspDB14 sensors with the wrist (23 DoFs, mode "full") on 10,000 frames
nf <- bq(10000, 1000)
g <- matrix(runif(nf * 23, -1.2, 0.3), 10000, 23, dimnames = list(NULL, joint_map("graspdb14")$dof))
g <- g[seq_len(nf), , drop = FALSE]
b <- bench::mark(forward_kinematics(g, skel, unit = "rad", mode = "full"), iterations = bq(10, 2), check = FALSE)
cat(sprintf("GraspDB14 23 sensors, full mode, %d frames: median %.0f ms (%.2f ms per 100 frames)\n",
            nf, as.numeric(b$median) * 1000, as.numeric(b$median) * 1000 / (nf / 100)))
