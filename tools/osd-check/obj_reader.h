// tessellab's own OBJ reading for the OpenSubdiv tools (osd_eval, osd_time): v, f in any
// index form, t crease/corner/hole/interpolateboundary/creasemethod with 0-based indices.
// No code from OpenSubdiv's examples is used.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

struct Obj {
    std::vector<double> pos;
    std::vector<int> counts, indices;
    std::vector<int> creasePairs;
    std::vector<float> creaseW;
    std::vector<int> cornerV;
    std::vector<float> cornerW;
    std::vector<int> holes;
    int boundary = -1;  // from file
    int chaikin = -1;
};

static bool readObj(const char *path, Obj &o) {
    std::ifstream in(path);
    if (!in) return false;
    std::string line, acc;
    std::vector<std::string> logical;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!line.empty() && line.back() == '\\') { acc += line.substr(0, line.size() - 1) + " "; continue; }
        logical.push_back(acc + line);
        acc.clear();
    }
    if (!acc.empty()) logical.push_back(acc);
    for (auto &l : logical) {
        size_t h = l.find('#');
        if (h != std::string::npos) l = l.substr(0, h);
        std::istringstream ss(l);
        std::string kw;
        if (!(ss >> kw)) continue;
        if (kw == "v") {
            double x, y, z;
            ss >> x >> y >> z;
            o.pos.push_back(x); o.pos.push_back(y); o.pos.push_back(z);
        } else if (kw == "f") {
            std::string tok;
            int n = 0;
            int nv = (int)o.pos.size() / 3;
            while (ss >> tok) {
                int i = std::atoi(tok.c_str());
                o.indices.push_back(i < 0 ? nv + i : i - 1);
                n++;
            }
            o.counts.push_back(n);
        } else if (kw == "t") {
            std::string name, cnt;
            ss >> name >> cnt;
            int ni = 0, nf = 0, ns = 0;
            std::sscanf(cnt.c_str(), "%d/%d/%d", &ni, &nf, &ns);
            std::vector<int> ints(ni);
            std::vector<float> fl(nf);
            std::vector<std::string> st(ns);
            for (auto &x : ints) ss >> x;
            for (auto &x : fl) { double d; ss >> d; x = (float)d; }
            for (auto &x : st) ss >> x;
            if (name == "crease") {
                for (int k = 0; k + 1 < ni; k += 2) {
                    o.creasePairs.push_back(ints[k]); o.creasePairs.push_back(ints[k + 1]);
                    o.creaseW.push_back(nf == 1 ? fl[0] : fl[k / 2]);
                }
            } else if (name == "corner") {
                for (int k = 0; k < ni; k++) { o.cornerV.push_back(ints[k]); o.cornerW.push_back(nf == 1 ? fl[0] : fl[k]); }
            } else if (name == "hole") {
                for (int k = 0; k < ni; k++) o.holes.push_back(ints[k]);
            } else if (name == "interpolateboundary" && ni == 1) {
                o.boundary = ints[0];
            } else if (name == "creasemethod" && ns == 1) {
                o.chaikin = st[0] == "chaikin" ? 1 : 0;
            }
        }
    }
    return true;
}
