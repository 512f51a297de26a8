// The frame shown at time t: the last one at or before t.
export function frameAt(times, t) {
    let lo = 0;
    let hi = times.length - 1;
    if (t >= times[hi]) return hi;
    while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (times[mid] <= t) lo = mid;
        else hi = mid - 1;
    }
    return lo;
}
