# Builds the documentation site with pkgdown as pkgdown::build_site() does
# (home, reference with its examples run, articles, news, sitemap, search
# index), but with the independent parts on both cores: the reference pages
# and each article are separate jobs handed to two forked R processes,
# longest first (each article is rendered in a fresh R process by pkgdown
# anyway, so they share nothing). On 2 cores this takes about half the time
# of one process doing them in turn; the pages are the same.
# The installed package is used (`devel = FALSE`: the examples run R's -O2
# build, as a user's; pkgload would compile the C code at -O0).
# Run from the repository root (tools/site.sh does).
pkg <- pkgdown::as_pkgdown(".")
pkgdown::init_site(pkg)
pkgdown::build_home(pkg, preview = FALSE)

# Jobs, the longest first (measured CPU seconds on the 2-core machine:
# the reference's examples ~35, recognition ~40, natural grasps ~26,
# reproduce-thesis ~16, own glove ~13, handover ~12, the rest a few each).
order <- c("recognition", "reference", "real-recordings", "natural-grasps", "reproduce-thesis", "own-glove", "handover")
articles <- as.character(pkg$vignettes$name)
jobs <- c(intersect(order, c("reference", articles)), setdiff(articles, order))
run_job <- function(job) {
  started <- proc.time()[["elapsed"]]
  if (job == "reference") {
    pkgdown::build_reference(pkg, lazy = FALSE, examples = TRUE, devel = FALSE, preview = FALSE)
  } else {
    pkgdown::build_article(job, pkg, lazy = FALSE)
  }
  proc.time()[["elapsed"]] - started
}
took <- parallel::mclapply(jobs, function(job) {
  tryCatch(run_job(job), error = function(e) e)
}, mc.cores = 2L, mc.preschedule = FALSE)
failed <- vapply(took, inherits, logical(1), "error")
if (any(failed)) {
  stop("site: building ", paste(jobs[failed], collapse = ", "), " failed: ",
       paste(vapply(took[failed], conditionMessage, character(1)), collapse = "; "), call. = FALSE)
}
message(paste(sprintf("site: %s %.0f s", jobs, unlist(took)), collapse = "\n"))
pkgdown::build_articles_index(pkg)
pkgdown::build_news(pkg, preview = FALSE)
pkgdown:::build_sitemap(pkg)   # (not exported; build_site() calls it)
pkgdown:::build_redirects(pkg)
pkgdown::build_search(pkg)
