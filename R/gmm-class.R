# Class "gmm_fit": a fitted Gaussian mixture (weights, means, covariances),
# with how it was fitted (log-likelihood, iterations, convergence, fallback
# and its reason, engine, n). Its one constructor and one validator, the
# argument check of the functions that take a fit, and print().

# The one constructor of class "gmm_fit" (the EM result, its fallbacks, and
# the point mass of a constant DoF all go through it).
new_gmm_fit <- function(weights, means, covs, loglik, iterations, converged, fallback, reason,
                        engine, n, point_mass = FALSE) {
  validate_gmm_fit(structure(
    list(weights = as.numeric(weights), means = means, covs = covs, loglik = loglik,
         iterations = as.integer(iterations), converged = converged, fallback = fallback,
         reason = reason, engine = engine, n = n, colnames = colnames(means),
         point_mass = point_mass),
    class = "gmm_fit"))
}

# The one validator: k components with a mean row and a d x d covariance
# each, and weights that are a probability vector.
validate_gmm_fit <- function(x) {
  k <- length(x$weights)
  d <- ncol(x$means)
  stopifnot(k >= 1L, nrow(x$means) == k, identical(dim(x$covs), c(d, d, k)),
            all(x$weights >= 0), abs(sum(x$weights) - 1) < 1e-8)
  x
}

# The argument check of the functions that take a fit (a classed error, not
# the validator's stop: a user may pass anything).
check_gmm_fit <- function(fit, call) {
  if (!inherits(fit, "gmm_fit")) {
    hm_abort("{.arg fit} must be a {.cls gmm_fit} object (from {.fn gmm_fit}).", "bad_input",
             argument = "fit", call = call)
  }
  invisible(fit)
}

#' @export
print.gmm_fit <- function(x, ...) {
  k <- length(x$weights)
  d <- ncol(x$means)
  n <- if (is.null(x$n)) "?" else format(x$n, scientific = FALSE)
  cli::cat_line(cli::pluralize("<gmm_fit> {k} component{?s} in {d} dimension{?s}, n = {n} ({x$engine} engine)"))
  it <- x$iterations
  its <- if (is.na(it)) "? EM iterations" else cli::pluralize("{it} EM iteration{?s}")
  cli::cat_line(sprintf("  log-likelihood %.4f after %s", x$loglik, its),
                if (isTRUE(x$converged)) " (converged)" else "")
  if (isTRUE(x$fallback)) cli::cat_line("  fallback: single Gaussian -- ", x$reason)
  tab <- data.frame(weight = x$weights, x$means, check.names = FALSE)
  names(tab)[-1] <- paste0("mean_", if (is.null(colnames(x$means))) seq_len(d) else colnames(x$means))
  print(tab, digits = 4, row.names = FALSE)
  invisible(x)
}
