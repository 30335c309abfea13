# Classed errors. Every error the package raises inherits from
# "handmotion_error" and carries a specific class, so callers (and the Python
# front end) can tell a bad file from a bad argument without parsing text.

#' Raise a classed handmotion error
#'
#' @param message A cli-formatted message (character vector; names give bullets).
#' @param class Short class name; the condition gets
#'   `c("handmotion_error_<class>", "handmotion_error")`.
#' @param ... Extra fields stored in the condition (e.g. `file`, `line`,
#'   `argument`, `recording`).
#' @param call The user-facing call to report, passed down from the exported
#'   function with `call = rlang::caller_env()`.
#' @param .envir Environment in which the cli message is interpolated.
#' @noRd
hm_abort <- function(message, class = "bad_input", ..., call = rlang::caller_env(),
                     .envir = parent.frame()) {
  cli::cli_abort(message,
                 class = c(paste0("handmotion_error_", class), "handmotion_error"),
                 ..., call = call, .envir = .envir)
}

#' Warn with a classed handmotion warning
#' @noRd
hm_warn <- function(message, class = "note", ..., .envir = parent.frame()) {
  cli::cli_warn(message,
                class = c(paste0("handmotion_warning_", class), "handmotion_warning"),
                ..., .envir = .envir)
}
