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

# Jobs, the longest first, so that two processes end together. The
# reference is two jobs (pkgdown::build_reference(topics =), each half of
# the help pages with its examples: one job of all 74 was the longest of
# the build). CPU seconds of each job (this process's and its children's:
# the R processes pkgdown renders each article in, the future workers) are
# printed beside its elapsed time, so a slow build says whether the work
# grew or the machine was busy.
topics <- pkg$topics$name
ref_jobs <- list(`reference (1/2)` = topics[c(TRUE, FALSE)], `reference (2/2)` = topics[c(FALSE, TRUE)])
# (CPU seconds of the jobs in a build at load 2-11: recognition 51, the
# second half of the reference 38, natural grasps 37, the first half 30,
# real recordings 24, reproduce-thesis and handover 20 each, own glove 18,
# the other three 8-11)
order <- c("recognition", "reference (2/2)", "natural-grasps", "reference (1/2)", "real-recordings",
           "reproduce-thesis", "handover", "own-glove", "graspdb14", "getting-started")
articles <- as.character(pkg$vignettes$name)
# the home page and the changelog (2-3 s of CPU each) fill the gaps at the
# end instead of running before and after the others
page_jobs <- list(home = function() pkgdown::build_home(pkg, preview = FALSE),
                  news = function() pkgdown::build_news(pkg, preview = FALSE))
jobs <- c(intersect(order, c(names(ref_jobs), articles)), setdiff(articles, order), names(page_jobs))
cpu_now <- function() sum(proc.time()[c("user.self", "sys.self", "user.child", "sys.child")], na.rm = TRUE)
run_job <- function(job) {
  started <- c(cpu = cpu_now(), elapsed = proc.time()[["elapsed"]])
  if (job %in% names(page_jobs)) {
    page_jobs[[job]]()
  } else if (job %in% names(ref_jobs)) {
    pkgdown::build_reference(pkg, lazy = FALSE, examples = TRUE, devel = FALSE, preview = FALSE,
                             topics = ref_jobs[[job]])
  } else {
    pkgdown::build_article(job, pkg, lazy = FALSE)
  }
  c(cpu = cpu_now(), elapsed = proc.time()[["elapsed"]]) - started
}
took <- parallel::mclapply(jobs, function(job) {
  tryCatch(run_job(job), error = function(e) e)
}, mc.cores = 2L, mc.preschedule = FALSE)
failed <- vapply(took, inherits, logical(1), "error")
if (any(failed)) {
  stop("site: building ", paste(jobs[failed], collapse = ", "), " failed: ",
       paste(vapply(took[failed], conditionMessage, character(1)), collapse = "; "), call. = FALSE)
}
took <- do.call(rbind, took)
load <- tryCatch(scan("/proc/loadavg", n = 1L, quiet = TRUE), error = function(e) NA_real_)
message(paste(c(sprintf("site: %-26s %6s %6s", "job", "elapsed", "CPU"),
                sprintf("site: %-26s %5.0f s %4.0f s", jobs, took[, "elapsed"], took[, "cpu"]),
                sprintf("site: %-26s %5s   %4.0f s (load average now %.1f)", "all jobs", "", sum(took[, "cpu"]), load)),
              collapse = "\n"))
pkgdown::build_articles_index(pkg)
pkgdown:::build_sitemap(pkg)   # (not exported; build_site() calls it)
pkgdown:::build_redirects(pkg)
pkgdown::build_search(pkg)
# The search index as a script as well: a page opened from file:// may load
# a script but not fetch() a JSON file (pkgdown/assets/pkgdown.js loads it).
writeLines(c("window.pkgdownSearchIndex = ", readLines("site/search.json", warn = FALSE), ";"), "site/search-index.js")
