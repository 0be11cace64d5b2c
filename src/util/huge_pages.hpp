#pragma once
// The memory a process holds, backed by huge pages before it forks many children: fork copies one
// page-table entry per 4 KiB page its parent has touched (copy_page_range, and each page's
// reference count), one per 2 MiB once they are collapsed. A batch's parent holds its cached
// scenes and their reference pictures (tens of megabytes) when it starts forking: about a second of
// `zcube reproduce`'s CPU went to copying their page tables, 300 times. A child reading that memory
// faults nothing; one writing into it copies 4 KiB, as before.
namespace zc {

// Collapses this process's anonymous private writable mappings of at least 4 MiB other than its
// heap (malloc's large blocks and the arenas of its threads: data written once, then read) into
// huge pages where the kernel can (MADV_COLLAPSE, Linux 6.1). The heap, which malloc keeps
// writing, stays as it is, and so do the mappings' later faults (4 KiB: nothing is marked for huge
// pages). Quietly does nothing where the kernel cannot.
void collapse_into_huge_pages();

} // namespace zc
