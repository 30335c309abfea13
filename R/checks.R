# Argument checkers: the one place where the package decides what a valid
# count, number, choice, seed or numeric matrix is. Each raises a
# `handmotion_error_bad_input` (see ?handmotion_errors) naming the argument and
# the user-facing call, and returns the value in the form the caller uses
# (integers as integer, matrices as double), so call sites read
#   k <- check_whole(k, "k", max = p, call = call)

# A single whole number in [min, max]; `allow_null` lets NULL through;
# `class` is the specific error class (a subclass of bad_input).
check_whole <- function(x, arg, min = 1, max = Inf, allow_null = FALSE, class = "bad_input",
                        call = rlang::caller_env()) {
  if (is.null(x) && allow_null) return(NULL)
  ok <- is.numeric(x) && length(x) == 1L && is.finite(x) && x == round(x) && x >= min && x <= max
  if (!ok) {
    num <- function(v) format(v, big.mark = ",", scientific = FALSE, trim = TRUE)
    range <- if (is.finite(max)) sprintf("from %s to %s", num(min), num(max))
             else if (min == 1) "positive" else if (min == 0) "non-negative" else sprintf("of at least %s", num(min))
    what <- if (is.finite(max) || min > 1) paste("a whole number", range) else paste("one", range, "whole number")
    hm_abort("{.arg {arg}} must be {what}, not {describe_value(x)}.",
             class, argument = arg, call = call)
  }
  # an integer where R's integers reach (callers index with it), else a whole double
  if (abs(x) <= .Machine$integer.max) as.integer(x) else as.double(x)
}

# A single finite number in [min, max] (or (min, max] with `min_open`);
# `unit` says what it counts, for the message ("frames per second").
check_number <- function(x, arg, min = -Inf, max = Inf, min_open = FALSE, allow_null = FALSE, unit = NULL,
                         call = rlang::caller_env()) {
  if (is.null(x) && allow_null) return(NULL)
  ok <- is.numeric(x) && length(x) == 1L && is.finite(x) && x <= max &&
    (if (min_open) x > min else x >= min)
  if (!ok) {
    bound <- if (min_open && min == 0 && !is.finite(max)) "a positive number"
             else if (min == 0 && !min_open && !is.finite(max)) "a non-negative number"
             else if (is.finite(min) || is.finite(max)) sprintf("a number %s %s%s", if (min_open) ">" else ">=",
                                                                format(min), if (is.finite(max)) sprintf(" and <= %s", format(max)) else "")
             else "one finite number"
    if (!is.null(unit)) bound <- paste(bound, "of", unit)
    hm_abort("{.arg {arg}} must be {bound}, not {describe_value(x)}.",
             "bad_input", argument = arg, call = call)
  }
  as.double(x)
}

# TRUE or FALSE (or NA with `allow_na`: "decide for me", as read_hust()'s
# `recursive`).
check_flag <- function(x, arg, allow_na = FALSE, call = rlang::caller_env()) {
  if (!is.logical(x) || length(x) != 1L || (is.na(x) && !allow_na)) {
    hm_abort(if (allow_na) "{.arg {arg}} must be {.code TRUE}, {.code FALSE} or {.code NA}, not {describe_value(x)}."
             else "{.arg {arg}} must be {.code TRUE} or {.code FALSE}, not {describe_value(x)}.",
             "bad_input", argument = arg, call = call)
  }
  x
}

# One non-missing string; `what` it is, for the message ("one file path").
check_string <- function(x, arg, what = "one string", call = rlang::caller_env()) {
  if (!is.character(x) || length(x) != 1L || is.na(x)) {
    hm_abort("{.arg {arg}} must be {what}, not {describe_value(x)}.",
             "bad_input", argument = arg, call = call)
  }
  x
}

# One of `choices` (by default the default of argument `arg` of the calling
# function, as match.arg() does): strings, or numbers (a speed of 0.5 or 1).
# The whole `choices` vector (an argument left at its default, here or in the
# verb that passed it on) means the first choice; `whole = FALSE` where the
# choices are no argument's default (fk_input()'s `unit`: `c("deg", "rad")`
# is two units, an error). A misspelt choice gets a classed error with the
# valid values and the closest one; `info` adds bullets saying why only these
# (plain text).
check_choice <- function(x, choices = NULL, arg, info = NULL, whole = TRUE, call = rlang::caller_env()) {
  if (is.null(choices)) {
    caller <- sys.function(sys.parent())
    choices <- eval(formals(caller)[[arg]], envir = environment(caller))
  }
  if (whole && identical(x, choices)) return(choices[1])
  # (of the choices' own type: "1" is not the speed 1, nor 1 the string "1")
  same_type <- if (is.numeric(choices)) is.numeric(x) else is.character(x)
  if (same_type && length(x) == 1L && !is.na(x) && x %in% choices) return(x)
  hint <- NULL
  if (is.character(x) && length(x) == 1L && !is.na(x)) {
    d <- utils::adist(x, choices, ignore.case = TRUE)[1, ]
    # a guess only when one choice is nearest ("5.9" is as near to "5.1" as
    # to "5.8": guessing one of them would mislead)
    if (min(d) <= max(2, nchar(x) %/% 3) && sum(d == min(d)) == 1L) {
      hint <- c(i = "Did you mean {.val {choices[which.min(d)]}}?")
    }
  }
  # (`info` is text, not a template: its braces are escaped)
  info <- if (length(info)) stats::setNames(gsub("([{}])", "\\1\\1", info), rep("i", length(info)))
  hm_abort(c("{.arg {arg}} must be one of {.or {.val {choices}}}, not {describe_value(x)}.", hint, info),
           "bad_input", argument = arg, call = call)
}

# A seed: NULL (use the current RNG stream) or one finite whole number.
check_seed <- function(seed, arg = "seed", call = rlang::caller_env()) {
  if (is.null(seed)) return(NULL)
  if (!is.numeric(seed) || length(seed) != 1L || !is.finite(seed) || seed != round(seed) ||
      abs(seed) > .Machine$integer.max) {
    hm_abort("{.arg {arg}} must be {.code NULL} or one whole number, not {describe_value(seed)}.",
             "bad_input", argument = arg, call = call)
  }
  as.integer(seed)
}

# A numeric matrix (a data frame or, with `vector`, a numeric vector taken as
# one column or one row), with at least `min_rows` x `min_cols` cells and, with
# `finite`, only finite values; returned as a double matrix. `what` says what
# the rows and columns are, for the message; a non-finite cell is named by
# `row_name` and `col_name` ("curve 3, point 7").
as_numeric_matrix <- function(x, arg, what = "", finite = TRUE, vector = c("column", "row", "none"),
                              min_rows = 1L, min_cols = 1L, ncol = NULL, row_name = "row",
                              col_name = "column", call = rlang::caller_env()) {
  vector <- vector[1]
  if (inherits(x, "fdata")) x <- x$data
  if (is.data.frame(x)) x <- as.matrix(x)
  if (is.numeric(x) && is.null(dim(x)) && vector != "none") {
    x <- if (vector == "column") matrix(x, ncol = 1L) else matrix(x, nrow = 1L)
  }
  if (!is.matrix(x) || !(is.numeric(x) || is.logical(x) && all(is.na(x)))) {
    hm_abort("{.arg {arg}} must be a numeric matrix{what}, not {describe_value(x)}.",
             "bad_input", argument = arg, call = call)
  }
  if (nrow(x) < min_rows || ncol(x) < min_cols) {
    hm_abort("{.arg {arg}} must have at least {min_rows} row{?s} and {min_cols} column{?s}{what}, not {nrow(x)} x {ncol(x)}.",
             "bad_input", argument = arg, call = call)
  }
  if (!is.null(ncol) && ncol(x) != ncol) {
    hm_abort("{.arg {arg}} must have {ncol} column{?s}{what}, not {ncol(x)}.",
             "bad_input", argument = arg, call = call)
  }
  if (finite) {
    bad <- which(!is.finite(x), arr.ind = TRUE)
    if (nrow(bad) > 0L) {
      hm_abort(c("{.arg {arg}} has {nrow(bad)} non-finite value{?s}.",
                 x = "First at {row_name} {bad[1, 1]}, {col_name} {bad[1, 2]}."),
               "bad_input", argument = arg, recording = bad[1, 1], call = call)
    }
  }
  storage.mode(x) <- "double"
  x
}

# Arguments passed through `...` to `fun` must be named arguments of `fun`
# (otherwise R's "unused argument" error would come from deep inside).
check_dots_for <- function(dots, fun, fun_name, exclude = character(), call = rlang::caller_env()) {
  if (length(dots) == 0L) return(invisible(dots))
  nms <- names(dots) %||% rep("", length(dots))
  unknown <- setdiff(nms, setdiff(names(formals(fun)), c("...", exclude)))
  if (length(unknown)) {
    shown <- ifelse(nzchar(unknown), unknown, "<unnamed>")
    # an argument the caller sets itself is not "unknown" to `fun`
    set_here <- intersect(unknown, exclude)
    hm_abort(c(if (length(set_here)) "{.arg ...} cannot set {.val {set_here}}: this function sets {?it/them} itself."
               else "{.arg ...} is passed to {.fn {fun_name}}, which has no argument{?s} {.val {shown}}.",
               renamed_argument_hints(unknown),
               i = "Arguments passed on must be named; see {.help [{.fn {fun_name}}](handmotion::{fun_name})}."),
             "bad_input", argument = "...", call = call)
  }
  invisible(dots)
}

# A renamed argument given to a verb by its old name is an error that says
# the new one, instead of R's "unused argument" or, worse, a partial match
# (fit_grasp_model(k = 2) of development versions would set `keep_data`,
# generate(models, grasp = ) would set `grasps`). `own` are the verb's own
# arguments: an old name that is still right for this verb (`grasp` of
# fit_grasp_model(), `markers` of forward_kinematics()) is not an error.
check_renamed_args <- function(given, fun_name, own = character(), call = rlang::caller_env()) {
  old <- setdiff(intersect(given, names(renamed_arguments)), own)
  if (length(old) == 0L) return(invisible())
  hm_abort(c("{.fn {fun_name}} has no argument{?s} {.val {old}}.", renamed_argument_hints(old),
             i = "See {.help [{.fn {fun_name}}](handmotion::{fun_name})}."),
           "bad_input", argument = old[1], call = call)
}

# `...` of a verb that takes no further arguments, there only so that an old
# argument name is a classed error naming the new one (not R's "unused
# argument"): any name given there is refused.
check_no_dots <- function(dots, fun_name, call = rlang::caller_env()) {
  if (length(dots) == 0L) return(invisible())
  given <- rlang::names2(dots)
  check_renamed_args(given, fun_name, call = call)
  shown <- ifelse(nzchar(given), given, "<unnamed>")
  hm_abort(c("{.fn {fun_name}} has no argument{?s} {.val {shown}}.",
             i = "See {.help [{.fn {fun_name}}](handmotion::{fun_name})}."),
           "bad_input", argument = "...", call = call)
}

# Arguments renamed before the first release (see ?handmotion-renamed), by
# what they count or to the word every other verb uses: one bullet per old
# name the caller used.
renamed_arguments <- c(
  k = paste("{.arg k} was renamed by what it counts: {.arg mixture_components} (fit_grasp_model(),",
            "fit_grasp_models()), {.arg ncomp} (last-frame PCs) or {.arg neighbours} (fit_handover())."),
  newdata = "{.arg newdata} is {.arg new_data}, as in every {.fn predict} method and {.fn autoplot} of a model.",
  grasp = paste("{.arg grasp} (the grasp types to select) is {.arg grasps}, as in {.fn fit_grasp_models}",
                "and {.fn simulate_grasps}."),
  overlong = paste("{.arg overlong} of {.fn simulate_grasps} (plant over-long recordings?) is",
                   "{.arg plant_overlong}; {.arg overlong} is the over-long rule of {.fn fit_grasp_model}."),
  markers = paste("{.arg markers} of {.fn fit_handover} is a marker set (names); a number of markers",
                  "to select is {.arg n_markers}."),
  loso_folds = "{.arg loso_folds} is {.arg folds} ({.code NULL}: one fold per subject), as in {.fn evaluate_loso}."
)

renamed_argument_hints <- function(nms) {
  hit <- intersect(nms, names(renamed_arguments))
  stats::setNames(unname(renamed_arguments[hit]), rep("i", length(hit)))
}

# Class labels asked for by name (or, for Feix-labelled data, by id):
# `grasps = ` of a fit, of generate() and of autoplot(). `levels` are the labels the
# data or models have; see resolve_labels().
check_grasp_selection <- function(grasps, arg, levels = NULL, call = rlang::caller_env()) {
  resolve_labels(grasps, levels, arg, call = call)
}

# The grasp types a fit found in `x` (`types`) must not be none: an empty
# selection and a set without labels are told apart (class no_labels).
check_some_types <- function(types, x, call = rlang::caller_env()) {
  if (length(types) == 0L) {
    hm_abort(if (length(x) == 0L) "{.arg x} holds no recordings (an empty selection?)." else
               "{.arg x} has no labelled recordings: every {.field grasp} is {.val NA}.",
             "no_labels", argument = "x", call = call)
  }
  invisible(types)
}

# A short description of an offending value for messages: the value itself
# when it is one short atom, otherwise its type and length.
describe_value <- function(x) {
  if (is.null(x)) return("NULL")
  # (a factor prints its labels: factor(2) would read as the number 2)
  if (is.factor(x)) return(sprintf("a factor of length %d", length(x)))
  if (is.atomic(x) && length(x) == 1L && is.null(dim(x))) {
    v <- if (is.character(x) && !is.na(x)) sprintf("\"%s\"", x) else format(x)
    if (nchar(v) <= 40) return(v)
  }
  if (is.atomic(x) && is.null(dim(x))) return(sprintf("a %s vector of length %d", typeof(x), length(x)))
  if (is.matrix(x)) return(sprintf("a %d x %d %s matrix", nrow(x), ncol(x), typeof(x)))
  paste0("an object of class <", paste(class(x), collapse = "/"), ">")
}

# One regular expression that compiles (`perl` as the caller will use it),
# or NULL with `allow_null`: an invalid one (an unclosed bracket) would
# otherwise fail in base R with "invalid regular expression", naming no
# argument.
check_regex <- function(x, arg, perl = FALSE, allow_null = FALSE, call = rlang::caller_env()) {
  if (is.null(x) && allow_null) return(NULL)
  if (!is.character(x) || length(x) != 1L || is.na(x)) {
    hm_abort("{.arg {arg}} must be one regular expression, not {describe_value(x)}.",
             "bad_input", argument = arg, call = call)
  }
  problem <- tryCatch({
    suppressWarnings(grepl(x, "", perl = perl))
    NULL
  }, error = function(e) conditionMessage(e))
  if (!is.null(problem)) {
    hm_abort(c("{.arg {arg}} is not a valid regular expression: {.val {x}}.",
               i = "{if (perl) 'A Perl-style' else 'An extended'} regular expression; see {.help base::regex}."),
             "bad_input", argument = arg, call = call)
  }
  x
}

# A field separator: one character, or NA (`allow_na`, detect it).
check_sep <- function(sep, arg = "sep", allow_na = TRUE, call = rlang::caller_env()) {
  if (allow_na && length(sep) == 1L && is.na(sep)) return(NA)
  if (!is.character(sep) || length(sep) != 1L || is.na(sep) || nchar(sep) != 1L || sep %in% c("\n", "\r", "\"")) {
    hm_abort("{.arg {arg}} must be one character such as {.val ,} or {.val ;}{if (allow_na) ' (or NA to detect it)' else ''}, not {describe_value(sep)}.",
             "bad_input", argument = arg, call = call)
  }
  sep
}

# Recordings of the grasps set `x` picked by index (whole numbers from 1 to
# length(x)) or id; returns their indices; `several` lets more than one
# through. A fractional index (2.5) used to be truncated silently, TRUE
# taken as 1.
check_recording_pick <- function(recording, x, arg = "recording", several = FALSE, call = rlang::caller_env()) {
  idx <- if (is.character(recording)) match(recording, x$meta$id) else recording
  where <- if (several) " or ids of `x`" else " or an id of `x`"
  check_indices(idx, length(x), arg, "recording", where = where, one = !several, given = recording, call = call)
}

# Whole-number positions in 1..n, at least one (exactly one with `one`) and
# no NA, as integers: the frames of a recording, the recordings of a set.
# `what` names one position ("frame"); `where` (plain text) says whose
# positions; `given` is what the user gave (ids before they were matched);
# `...` are the error's fields (recording = id). A fractional position (2.5)
# used to be truncated silently.
check_indices <- function(i, n, arg, what, where = "", one = FALSE, given = i, ...,
                          call = rlang::caller_env()) {
  if (!is.numeric(i) || !length(i) || (one && length(i) != 1L) || anyNA(i) || any(i != round(i)) ||
      any(i < 1 | i > n)) {
    hm_abort("{.arg {arg}} must be {if (one) 'one whole' else 'whole'} {what} number{if (one) '' else 's'} from 1 to {n}{where}, not {describe_value(given)}.",
             "bad_input", argument = arg, ..., call = call)
  }
  as.integer(i)
}

# Numeric subscripts of a set of `n` `what`s (`[` methods): whole numbers,
# all positive (1..n) or all negative (dropping -1..-n), no NA. R's own
# subsetting truncates 2.5 to 2 and ignores -99 without a word.
check_positions <- function(i, n, what, call = rlang::caller_env()) {
  if (!is.numeric(i) || anyNA(i) || any(i != round(i))) {
    hm_abort("{.arg i} must be whole {what} numbers, ids or a logical vector, not {describe_value(i)}.",
             "bad_input", argument = "i", call = call)
  }
  if (length(i) && (any(i > n) || any(i < -n) || (any(i < 0) && any(i > 0)))) {
    hm_abort("{.arg i} must lie in 1..{n} (or -{n}..-1 to drop), not mix signs: the set has {n} {what}{?s}.",
             "bad_input", argument = "i", call = call)
  }
  seq_len(n)[i]
}
