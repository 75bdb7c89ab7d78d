#include "AMRDualMeshRedistribution.h"

#include "AMRDualMeshDistribution.h"
#include "AMRDualMeshProxy.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkOverlappingAMR.h"

#include <chrono>
#include <climits>
#include <vector>

namespace amrdm_vtk
{
namespace
{
/// True on every rank when `ok` holds on every rank.
bool AllOk(vtkMultiProcessController* c, bool ok)
{
  const int mine = ok ? 1 : 0;
  int all = 0;
  c->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}

/// All-to-all of byte buffers: one Gather + GatherV per destination rank (collectives only,
/// so no ordering of point-to-point messages can deadlock).
bool Exchange(vtkMultiProcessController* c,
  const std::vector<std::vector<char>>& outgoing,
  std::vector<std::vector<char>>& incoming,
  std::string& error)
{
  const int n = c->GetNumberOfProcesses(), rank = c->GetLocalProcessId();
  incoming.assign(static_cast<std::size_t>(n), {});
  bool fits = true;
  for (const std::vector<char>& b : outgoing)
  {
    fits = fits && b.size() < std::size_t(INT_MAX);
  }
  if (!AllOk(c, fits))
  {
    error = "a rank has more than 2 GiB of blocks for one region; expected less per message "
            "(use more ranks)";
    return false;
  }
  std::vector<unsigned long long> lengths(static_cast<std::size_t>(n));
  std::vector<vtkIdType> counts(static_cast<std::size_t>(n)), offsets(static_cast<std::size_t>(n));
  std::vector<char> all;
  const char dummy = 0;
  for (int root = 0; root < n; ++root)
  {
    const std::vector<char>& send = outgoing[static_cast<std::size_t>(root)];
    const unsigned long long length = send.size();
    c->Gather(&length, lengths.data(), 1, root);
    vtkIdType total = 0;
    if (rank == root)
    {
      for (int r = 0; r < n; ++r)
      {
        counts[static_cast<std::size_t>(r)] = static_cast<vtkIdType>(lengths[r]);
        offsets[static_cast<std::size_t>(r)] = total;
        total += counts[static_cast<std::size_t>(r)];
      }
      all.resize(static_cast<std::size_t>(total) + 1);
    }
    c->GatherV(send.empty() ? &dummy : send.data(),
      rank == root ? all.data() : nullptr,
      static_cast<vtkIdType>(send.size()),
      counts.data(),
      offsets.data(),
      root);
    if (rank == root)
    {
      for (int r = 0; r < n; ++r)
      {
        const char* p = all.data() + offsets[static_cast<std::size_t>(r)];
        incoming[static_cast<std::size_t>(r)].assign(p, p + counts[static_cast<std::size_t>(r)]);
      }
      std::vector<char>().swap(all);
    }
  }
  return true;
}
}

bool RedistributeAMR(vtkMultiProcessController* controller,
  vtkOverlappingAMR* input,
  bool replicate,
  bool proxy,
  RegionData& out,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  out = RegionData();
  vtkMultiProcessController* c = controller;
  out.NumRanks = c->GetNumberOfProcesses();
  out.Rank = c->GetLocalProcessId();
  AMRPartition partition;
  // The metadata is the same on every rank, so is the outcome; it is agreed on all the same.
  const bool partitioned = PartitionAMR(input, out.NumRanks, partition, error);
  if (!AllOk(c, partitioned))
  {
    if (partitioned)
    {
      error = "another rank could not partition the AMR domain";
    }
    return false;
  }
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(out.NumRanks));
  bool packed = true;
  for (int r = 0; r < out.NumRanks && packed; ++r)
  {
    packed = PackRegionPieces(input, partition, r, replicate, outgoing[r], error);
  }
  if (!AllOk(c, packed))
  {
    if (packed)
    {
      error = "another rank could not cut its blocks for the regions";
    }
    return false;
  }
  for (const std::vector<char>& b : outgoing)
  {
    out.BytesSent += static_cast<long long>(b.size());
  }
  std::vector<std::vector<char>> incoming;
  if (!Exchange(c, outgoing, incoming, error))
  {
    return false;
  }
  outgoing.clear();
  for (const std::vector<char>& b : incoming)
  {
    out.BytesReceived += static_cast<long long>(b.size());
  }
  out.Local = AssembleRegion(input, incoming, error);
  if (!AllOk(c, out.Local != nullptr))
  {
    if (out.Local)
    {
      error = "another rank could not assemble its region";
    }
    out.Local = nullptr;
    return false;
  }
  if (proxy && !replicate)
  {
    // Every rank's level-0 blocks to every rank (an all-gather of a small buffer).
    std::vector<char> coarse;
    const bool ok = PackCoarseBlocks(input, coarse, error);
    if (!AllOk(c, ok))
    {
      if (ok)
      {
        error = "another rank could not pack its level-0 blocks for the proxy";
      }
      out.Local = nullptr;
      return false;
    }
    outgoing.assign(static_cast<std::size_t>(out.NumRanks), coarse);
    out.BytesSent += static_cast<long long>(coarse.size()) * out.NumRanks;
    if (!Exchange(c, outgoing, incoming, error))
    {
      out.Local = nullptr;
      return false;
    }
    outgoing.clear();
    for (const std::vector<char>& b : incoming)
    {
      out.BytesReceived += static_cast<long long>(b.size());
    }
    out.Proxy = AssembleCoarse(input, incoming, kProxyMaxCells, error);
    if (!AllOk(c, out.Proxy != nullptr))
    {
      if (out.Proxy)
      {
        error = "another rank could not assemble the proxy";
      }
      out.Local = out.Proxy = nullptr;
      return false;
    }
  }
  out.Region = partition.Regions[static_cast<std::size_t>(out.Rank)];
  out.Domain = partition.Domain;
  out.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}
}
