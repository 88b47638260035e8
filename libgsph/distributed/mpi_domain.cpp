// SPDX-License-Identifier: MIT
#include "distributed/mpi_domain.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "distributed/halo_plan.hpp"

namespace gsph {
namespace {

void check(int status, const char* call) {
    if (status != MPI_SUCCESS) throw Error(std::string("MPI: ") + call + " failed");
}

// The gather's messages: a tag apart from the exchanges' (GhostColumns), and at most 1 GiB each.
constexpr int kGatherTag = 64;
constexpr std::size_t kMessageBytes = std::size_t{1} << 30;

class MpiDomain final : public Domain {
  public:
    MpiDomain() {
        check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
        check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
    }

    ParticleRange split(const Reference& ref, const std::vector<StencilBlocks>& blocks,
                        bool cutStrided) override {
        cuts_ = cutByCost(blocks, ref.size(), size_, cutStrided);
        peers_ = planHalo(pairReads(ref), cuts_, rank_);
        halos_.clear();
        pairs_ = &ref.pairs;
        ghosts_.clear();
        for (const HaloPeer& peer : peers_)  // peers ascending, each one's range after the last's
            ghosts_.insert(ghosts_.end(), peer.receive.begin(), peer.receive.end());
        pairCuts_.clear();
        for (Index c : cuts_)
            pairCuts_.push_back(c < ref.size() ? ref.pairs.begin(c) : ref.pairs.pairs());
        describeSplit(costsOf(blocks, cuts_));
        const auto r = static_cast<std::size_t>(rank_);
        return {cuts_[r], cuts_[r + 1]};
    }
    int processes() const override { return size_; }
    bool writesFiles() const override { return rank_ == 0; }

    void shareGhosts(GhostColumns which, std::span<const GhostArray> arrays) override {
        const std::vector<HaloPeer>& peers = peersOf(which);
        std::size_t entry = 0;
        for (const GhostArray& array : arrays) entry += array.entryBytes;
        exchange(
            which, peers,
            [&](std::size_t p, bool sending) {
                const HaloPeer& peer = peers[p];
                return (sending ? peer.send.size() : peer.receive.size()) * entry;
            },
            [&](std::size_t p, std::uint8_t* out) {
                for (const GhostArray& array : arrays) {
                    const auto* data = static_cast<const std::uint8_t*>(array.data);
                    for (Index a : peers[p].send) {
                        std::memcpy(out, data + static_cast<std::size_t>(a) * array.entryBytes,
                                    array.entryBytes);
                        out += array.entryBytes;
                    }
                }
            },
            [&](std::size_t p, const std::uint8_t* in) {
                for (const GhostArray& array : arrays) {
                    auto* data = static_cast<std::uint8_t*>(array.data);
                    for (Index a : peers[p].receive) {
                        std::memcpy(data + static_cast<std::size_t>(a) * array.entryBytes, in,
                                    array.entryBytes);
                        in += array.entryBytes;
                    }
                }
            });
    }

    void addHalo(GhostColumns which, const Reads& reads, const std::string& what) override {
        halos_.push_back({which, planHalo(reads, cuts_, rank_)});
        const auto [total, most] = ghostCounts(halos_.back().peers);
        description_ += "; " + what + ": " + std::to_string(total) +
                        " ghosts of its own (at most " + std::to_string(most) + " on one)";
    }

    std::span<const Index> ghosts() const override { return ghosts_; }

    void shareGhostRows(std::span<std::uint8_t> perPair) override {
        const PairList& P = *pairs_;
        const auto rows = [&](const std::vector<Index>& particles) {
            std::size_t n = 0;
            for (Index a : particles) n += static_cast<std::size_t>(P.end(a) - P.begin(a));
            return n;
        };
        exchange(
            GhostColumns::BondRows, peers_,
            [&](std::size_t p, bool sending) {
                return rows(sending ? peers_[p].send : peers_[p].receive);
            },
            [&](std::size_t p, std::uint8_t* out) {
                for (Index a : peers_[p].send)
                    out = std::copy(perPair.begin() + P.begin(a), perPair.begin() + P.end(a), out);
            },
            [&](std::size_t p, const std::uint8_t* in) {
                for (Index a : peers_[p].receive) {
                    const auto n = static_cast<std::size_t>(P.end(a) - P.begin(a));
                    std::copy(in, in + n, perPair.begin() + P.begin(a));
                    in += n;
                }
            });
    }

    void shareListed(std::span<const Index> mine, double reach, std::vector<Vec3>& x,
                     std::vector<std::uint8_t>& flags, std::vector<Index>& received) override {
        const auto processes = static_cast<std::size_t>(size_);
        const auto self = static_cast<std::size_t>(rank_);
        // Every process's box of its listed positions (empty: +inf lower, −inf upper).
        constexpr double inf = std::numeric_limits<double>::infinity();
        double box[6] = {inf, inf, inf, -inf, -inf, -inf};
        for (Index a : mine)
            for (int d = 0; d < 3; ++d) {
                const double v = x[static_cast<std::size_t>(a)][d];
                box[d] = std::min(box[d], v);
                box[3 + d] = std::max(box[3 + d], v);
            }
        boxes_.resize(6 * processes);
        check(MPI_Allgather(box, 6, MPI_DOUBLE, boxes_.data(), 6, MPI_DOUBLE, MPI_COMM_WORLD),
              "MPI_Allgather");
        // To each other process, the listed particles within reach of its box: index, position
        // (and flag), in ascending order.
        const std::size_t entry = sizeof(Index) + sizeof(Vec3) + (flags.empty() ? 0 : 1);
        sendCounts_.assign(processes, 0);
        outgoingListed_.clear();
        for (std::size_t q = 0; q < processes; ++q) {
            if (q == self) continue;
            const double* other = &boxes_[6 * q];
            const std::size_t start = outgoingListed_.size();
            for (Index a : mine) {
                const Vec3& xa = x[static_cast<std::size_t>(a)];
                bool near = true;
                for (int d = 0; d < 3 && near; ++d)
                    near = xa[d] >= other[d] - reach && xa[d] <= other[3 + d] + reach;
                if (!near) continue;
                const std::size_t at = outgoingListed_.size();
                outgoingListed_.resize(at + entry);
                std::uint8_t* out = outgoingListed_.data() + at;
                std::memcpy(out, &a, sizeof(Index));
                std::memcpy(out + sizeof(Index), xa.data(), sizeof(Vec3));
                if (!flags.empty())
                    out[sizeof(Index) + sizeof(Vec3)] = flags[static_cast<std::size_t>(a)];
            }
            sendCounts_[q] = static_cast<int>(outgoingListed_.size() - start);
        }
        receiveCounts_.resize(processes);
        check(MPI_Alltoall(sendCounts_.data(), 1, MPI_INT, receiveCounts_.data(), 1, MPI_INT,
                           MPI_COMM_WORLD),
              "MPI_Alltoall");
        sendOffsets_.resize(processes);
        receiveOffsets_.resize(processes);
        int sent = 0, got = 0;
        for (std::size_t q = 0; q < processes; ++q) {
            sendOffsets_[q] = sent;
            receiveOffsets_[q] = got;
            sent += sendCounts_[q];
            got += receiveCounts_[q];
        }
        incomingListed_.resize(static_cast<std::size_t>(got));
        check(MPI_Alltoallv(outgoingListed_.data(), sendCounts_.data(), sendOffsets_.data(),
                            MPI_BYTE, incomingListed_.data(), receiveCounts_.data(),
                            receiveOffsets_.data(), MPI_BYTE, MPI_COMM_WORLD),
              "MPI_Alltoallv");
        received.clear();
        for (const std::uint8_t* in = incomingListed_.data();
             in < incomingListed_.data() + incomingListed_.size(); in += entry) {
            Index b;
            std::memcpy(&b, in, sizeof(Index));
            const auto ib = static_cast<std::size_t>(b);
            std::memcpy(x[ib].data(), in + sizeof(Index), sizeof(Vec3));
            if (!flags.empty()) flags[ib] = in[sizeof(Index) + sizeof(Vec3)];
            received.push_back(b);
        }
        sent_.contact += static_cast<double>(sent);
    }

    BytesSent bytesSent() const override { return sent_; }

    double minimum(double local) override {
        double global = local;
        check(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD),
              "MPI_Allreduce");
        return global;
    }

    void minimum(std::span<double> values) override {
        check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()),
                            MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD),
              "MPI_Allreduce");
    }

    void sum(std::span<ExactSum> values) override {
        const std::size_t words = ExactSum::kWords;
        exactWords_.resize(values.size() * words);
        for (std::size_t k = 0; k < values.size(); ++k)
            values[k].toWords(
                std::span<std::int64_t, ExactSum::kWords>(&exactWords_[k * words], words));
        // Integers: their sum is exact, whatever order MPI adds them in.
        check(MPI_Allreduce(MPI_IN_PLACE, exactWords_.data(), static_cast<int>(exactWords_.size()),
                            MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD),
              "MPI_Allreduce");
        for (std::size_t k = 0; k < values.size(); ++k)
            values[k].fromWords(
                std::span<const std::int64_t, ExactSum::kWords>(&exactWords_[k * words], words));
    }

    bool any(bool local) override {
        int mine = local ? 1 : 0, some = 0;
        check(MPI_Allreduce(&mine, &some, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
        return some != 0;
    }

    void gather(State& state) override {
        state.forEachArray([&](const Field& field, auto& array) {
            if (array.empty()) return;
            if (field.extent != Extent::Particle && field.extent != Extent::Pair) return;
            using T = typename std::decay_t<decltype(array)>::value_type;
            const std::vector<Index>& cuts = field.extent == Extent::Particle ? cuts_ : pairCuts_;
            auto* data = reinterpret_cast<std::uint8_t*>(array.data());
            // Process by process into process 0's array, in messages of at most kMessageBytes
            // (MPI counts are ints): an array of any size.
            for (int r = 1; r < size_; ++r) {
                if (rank_ != 0 && rank_ != r) continue;
                const auto rr = static_cast<std::size_t>(r);
                const std::size_t begin = static_cast<std::size_t>(cuts[rr]) * sizeof(T);
                const std::size_t end = static_cast<std::size_t>(cuts[rr + 1]) * sizeof(T);
                for (std::size_t at = begin; at < end; at += kMessageBytes) {
                    const auto n = static_cast<int>(std::min(kMessageBytes, end - at));
                    if (rank_ == r)
                        check(MPI_Send(data + at, n, MPI_BYTE, 0, kGatherTag, MPI_COMM_WORLD),
                              "MPI_Send");
                    else
                        check(MPI_Recv(data + at, n, MPI_BYTE, r, kGatherTag, MPI_COMM_WORLD,
                                       MPI_STATUS_IGNORE),
                              "MPI_Recv");
                }
            }
        });
    }

    std::string describe() const override { return description_; }

  private:
    // One message to and from every peer, all at once: `bytes(p, sending)` their sizes,
    // `pack(p, out)` fills the one to peer p, `unpack(p, in)` reads the one from it.
    template <class Bytes, class Pack, class Unpack>
    void exchange(GhostColumns which, const std::vector<HaloPeer>& peers, Bytes&& bytes,
                  Pack&& pack, Unpack&& unpack) {
        const int tag = static_cast<int>(which);
        if (outgoing_.size() < peers.size()) {
            outgoing_.resize(peers.size());
            incoming_.resize(peers.size());
        }
        requests_.resize(2 * peers.size());
        for (std::size_t p = 0; p < peers.size(); ++p) {
            std::vector<std::uint8_t>& out = outgoing_[p];
            out.resize(bytes(p, true));
            pack(p, out.data());
            sent_.ghosts += static_cast<double>(out.size());
            incoming_[p].resize(bytes(p, false));
            for (const std::size_t n : {out.size(), incoming_[p].size()})
                if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
                    throw InputError(
                        "a split run's ghost exchange exceeds 2 GB per message: "
                        "run on more processes");
            check(MPI_Irecv(incoming_[p].data(), static_cast<int>(incoming_[p].size()), MPI_BYTE,
                            peers[p].process, tag, MPI_COMM_WORLD, &requests_[2 * p]),
                  "MPI_Irecv");
            check(MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_BYTE, peers[p].process,
                            tag, MPI_COMM_WORLD, &requests_[2 * p + 1]),
                  "MPI_Isend");
        }
        check(
            MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE),
            "MPI_Waitall");
        for (std::size_t p = 0; p < peers.size(); ++p) unpack(p, incoming_[p].data());
    }

    // The peers of the exchanges tagged `which`: a halo of their own (addHalo), or the pairs'.
    const std::vector<HaloPeer>& peersOf(GhostColumns which) const {
        for (const Halo& halo : halos_)
            if (halo.which == which) return halo.peers;
        return peers_;
    }

    // A halo's ghosts over all processes and the most on one (collective).
    std::pair<long, long> ghostCounts(const std::vector<HaloPeer>& peers) const {
        long mine = 0;
        for (const HaloPeer& peer : peers) mine += static_cast<long>(peer.receive.size());
        long total = 0, most = 0;
        check(MPI_Allreduce(&mine, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
        check(MPI_Allreduce(&mine, &most, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
        return {total, most};
    }

    // Ghosts over all processes and the most on one, and the bytes a step exchanges: per ghost,
    // x and v (6 doubles) and the force factors (K, N, F: 27, and c, ρ, α, s: 4); bonds that
    // break add the damage and σ, and their rows when some break.
    void describeSplit(const std::vector<std::ptrdiff_t>& costs) {
        const auto [total, most] = ghostCounts(peers_);
        std::string cuts;
        for (std::size_t r = 1; r + 1 < cuts_.size(); ++r)
            cuts += (r > 1 ? ", " : "") + std::to_string(cuts_[r]);
        std::ptrdiff_t all = 0, largest = 0;
        for (std::ptrdiff_t c : costs) {
            all += c;
            largest = std::max(largest, c);
        }
        char line[400];
        std::snprintf(line, sizeof line,
                      "split over %d processes at particles %s (the dearest process has %.3g of "
                      "an equal share of the cost); %ld ghosts (at most %ld on one), %.1f kB "
                      "exchanged per step",
                      size_, cuts.c_str(),
                      static_cast<double>(largest) * size_ /
                          static_cast<double>(std::max<std::ptrdiff_t>(all, 1)),
                      total, most, static_cast<double>(total) * 37 * 8 / 1e3);
        description_ = line;
    }

    std::string description_;
    // shareListed's buffers.
    std::vector<double> boxes_;
    std::vector<int> sendCounts_, receiveCounts_, sendOffsets_, receiveOffsets_;
    std::vector<std::uint8_t> outgoingListed_, incomingListed_;
    BytesSent sent_;
    int rank_ = 0, size_ = 1;
    std::vector<Index> cuts_;
    std::vector<HaloPeer> peers_;  ///< the pairs' halo
    struct Halo {
        GhostColumns which;
        std::vector<HaloPeer> peers;
    };
    std::vector<Halo> halos_;      ///< halos of their own (addHalo)
    std::vector<Index> pairCuts_;  ///< the first pair (CSR entry) of each process's particles
    std::vector<Index> ghosts_;    ///< every peer's receive list, ascending
    const PairList* pairs_ = nullptr;
    std::vector<std::vector<std::uint8_t>> outgoing_, incoming_;
    std::vector<MPI_Request> requests_;
    std::vector<std::int64_t> exactWords_;  ///< scratch of the exact sums
};

}  // namespace

std::shared_ptr<Domain> makeMpiDomain() {
    return std::make_shared<MpiDomain>();
}

}  // namespace gsph
