/* The permutation distribution of the unbiased squared MMD (evaluate_generation()).
 * K is the kernel matrix of the pooled sample (the first n rows the first sample,
 * the other m the second). Statistic 0 is the observed split; statistic k (1..P)
 * splits by a random permutation drawn exactly as sample.int(n + m) draws it
 * (R_unif_index() on a shrinking pool, every one of the N draws made), so the
 * session's RNG stream and the permutations are those of the R code it replaces.
 * Of the three kernel sums only the within-first-sample one needs the pairs of
 * the split; the cross and within-second ones follow from K's row sums and
 * total: sum(K[a, b]) = sum_a rowsum_a - sum(K[a, a]), and
 * sum(K[b, b]) = total - 2 sum(K[a, b]) - sum(K[a, a]). That is n^2 / 2 additions
 * per permutation instead of a product of K with a membership matrix (N^2 each). */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Random.h>

static double mmd_split(const double *K, int N, int n, const int *a, const double *rows,
                        double total, double diag_total) {
  int m = N - n;
  double aa = 0, ra = 0, da = 0;
  for (int i = 0; i < n; i++) {
    const double *col = K + (R_xlen_t) a[i] * N;
    double s = 0;
    for (int j = 0; j < i; j++) s += col[a[j]];
    aa += 2 * s;
    da += col[a[i]];
    ra += rows[a[i]];
  }
  double ab = ra - aa - da;              /* sum(K[a, b]) */
  double db = diag_total - da;
  double bb = total - 2 * ab - aa - da - db;  /* sum over b != b' */
  return aa / ((double) n * (n - 1)) + bb / ((double) m * (m - 1)) - 2 * ab / ((double) n * m);
}

SEXP hm_mmd_permutations(SEXP K_, SEXP n_, SEXP perms_) {
  int N = nrows(K_);
  if (TYPEOF(K_) != REALSXP || ncols(K_) != N) error("hm_mmd_permutations: 'K' must be a square double matrix");
  int n = asInteger(n_), P = asInteger(perms_);
  if (n < 2 || N - n < 2 || P < 0) error("hm_mmd_permutations: need two or more rows in each sample");
  const double *K = REAL(K_);
  double *rows = (double *) R_alloc(N, sizeof(double));
  double total = 0, diag_total = 0;
  for (int i = 0; i < N; i++) rows[i] = 0;
  for (int j = 0; j < N; j++) {
    const double *col = K + (R_xlen_t) j * N;
    for (int i = 0; i < N; i++) rows[i] += col[i];
    diag_total += col[j];
  }
  for (int i = 0; i < N; i++) total += rows[i];
  int *pool = (int *) R_alloc(N, sizeof(int));
  int *a = (int *) R_alloc(N, sizeof(int));
  char *in_a = (char *) R_alloc(N, sizeof(char));
  SEXP out = PROTECT(allocVector(REALSXP, P + 1));
  double *stat = REAL(out);
  for (int i = 0; i < n; i++) a[i] = i;
  stat[0] = mmd_split(K, N, n, a, rows, total, diag_total);
  GetRNGstate();
  for (int k = 1; k <= P; k++) {
    if (k % 16 == 0) R_CheckUserInterrupt();
    for (int i = 0; i < N; i++) { pool[i] = i; in_a[i] = 0; }
    int left = N;
    for (int i = 0; i < N; i++) {       /* sample.int(N): all N draws */
      int j = (int) R_unif_index(left);
      if (i < n) in_a[pool[j]] = 1;
      pool[j] = pool[--left];
    }
    /* the first sample's members in index order, so that a split sums the
       same terms in the same order whichever permutation gave it */
    int c = 0;
    for (int i = 0; i < N; i++) if (in_a[i]) a[c++] = i;
    stat[k] = mmd_split(K, N, n, a, rows, total, diag_total);
  }
  PutRNGstate();
  UNPROTECT(1);
  return out;
}
