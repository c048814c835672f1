/* A measurement aid for `eval peers` with the PCL ICP peer, never linked into shelfdock.
 *
 * PCL's k-d tree (FLANN) opens an OpenMP parallel region for every nearest-neighbour query, even
 * with one thread; on this project's virtual machine libgomp then makes futex system calls per
 * query, which dominate the ICP peer's time. Preloaded, this runs each region inline on the
 * calling thread, so the ICP peer's time is its own work (same results, the regions being
 * single-threaded anyway):
 *
 *   gcc -O2 -shared -fPIC -o /tmp/libgomp_inline.so scripts/gomp_inline.c
 *   LD_PRELOAD=/tmp/libgomp_inline.so build-pcl/bin/shelfdock eval peers
 *
 * Only the four libgomp symbols the k-d tree calls are replaced; shelfdock itself has no OpenMP.
 */
void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags) {
  (void)num_threads;
  (void)flags;
  fn(data);
}
void GOMP_barrier(void) {}
int omp_get_num_threads(void) { return 1; }
int omp_get_thread_num(void) { return 0; }
