#version 460
#extension GL_GOOGLE_include_directive : require
// tinybvh's closest-hit traversal of its compressed wide BVH (BVH8_CWBVH, Ylitie et al. 2017), traverse_cwbvh from
// jbikker/tinybvh traverse_cwbvh.cl (commit 4735685, MIT, third_party/tinybvh/LICENSE; itself after CUDA code by
// AlanWBFT), ported from OpenCL C to GLSL line by line, as a peer to vkmc's walk. Kept as tinybvh runs it on a GPU
// it does not recognise (traverse.cl: SIMD_AABBTEST, no USE_VLOAD_VSTORE, STACK_SIZE 32, uncompressed triangles,
// the portable forms of __bfind, __popc, sign_extend_s8x4 and UPDATE_HITMASK*), 64 invocations a group as its
// batch kernel is run. Spelt out in GLSL: as_char4 and as_uchar4 (byte extracts), as_float and as_uint (bit
// casts), 31 - clz (findMSB), popcount (bitCount); __bfind and __popc lose their underscores (reserved in GLSL);
// its step counter is kept for the counting variant only (the batch kernel passes none).
#include "tinybvh_bindings.h"

layout (local_size_x = 64) in;

layout (std430) buffer;

layout (binding = TINYBVH_BINDING_NODES) readonly buffer N { vec4 cwbvhNodes[]; };
layout (binding = TINYBVH_BINDING_TRIANGLES) readonly buffer T { vec4 cwbvhTris[]; };
layout (binding = TINYBVH_BINDING_HITS) writeonly buffer O { vec4 hit[]; } result;
layout (binding = TINYBVH_BINDING_RAYS) readonly buffer R { TestRay ray[]; } rayData;
layout (push_constant, std430) uniform Push { PushConstants pc; };

// vkmc's addition, in the counting variants only (TINYBVH_WALK_STATS; the timed kernels have none of it): each
// ray's loop iterations and triangle tests.
#ifdef TINYBVH_WALK_STATS
layout (binding = TINYBVH_BINDING_WALK_STATS) writeonly buffer S { uvec2 walkStats[]; };
uint statSteps = 0, statTests = 0;
#define COUNT(x) x
#else
#define COUNT(x)
#endif

// BVH traversal stack size (traverse.cl)
#define STACK_SIZE 32

uint bfind( const uint v ) { return uint( findMSB( v ) ); } // 31 - clz( v ): only correct if v cannot be zero
uint popc( const uint v ) { return uint( bitCount( v ) ); }
float fmin_fmin( const float a, const float b, const float c ) { return min( min( a, b ), c ); }
float fmax_fmax( const float a, const float b, const float c ) { return max( max( a, b ), c ); }

#define STACK_POP(X) { X = stack[--stackPtr]; }
#define STACK_PUSH(X) { stack[stackPtr++] = X; }

uint sign_extend_s8x4( const uint i )
{
	// docs: "with the given parameters, prmt will extend the sign to all bits in a byte."
	const uint b0 = (i & 0x80000000u) != 0 ? 0xff000000u : 0;
	const uint b1 = (i & 0x00800000u) != 0 ? 0x00ff0000u : 0;
	const uint b2 = (i & 0x00008000u) != 0 ? 0x0000ff00u : 0;
	const uint b3 = (i & 0x00000080u) != 0 ? 0x000000ffu : 0;
	return b0 + b1 + b2 + b3; // probably can do better than this.
}
#define UPDATE_HITMASK hitmask = (child_bits4 & 255) << (bit_index4 & 31)
#define UPDATE_HITMASK0 hitmask |= (child_bits4 & 255) << (bit_index4 & 31)
#define UPDATE_HITMASK1 hitmask |= ((child_bits4 >> 8) & 255) << ((bit_index4 >> 8) & 31);
#define UPDATE_HITMASK2 hitmask |= ((child_bits4 >> 16) & 255) << ((bit_index4 >> 16) & 31);
#define UPDATE_HITMASK3 hitmask |= (child_bits4 >> 24) << (bit_index4 >> 24);

// as_char4( x ).c and convert_float4( as_uchar4( x ) )
int as_char( const float x, const int c ) { return bitfieldExtract( floatBitsToInt( x ), 8 * c, 8 ); }
vec4 as_uchar4_float4( const float x ) { const uint u = floatBitsToUint( x ); return vec4( uvec4( u, u >> 8, u >> 16, u >> 24 ) & 255u ); }

// kernel
// based on CUDA code by AlanWBFT https://github.com/AlanIWBFT

vec4 traverse_cwbvh( const vec4 O, const vec4 D, const vec4 rD, const float t )
{
	// initialize ray
	vec4 hit = vec4( t, 0, 0, 0 ); // not fetching t from ray data to avoid one memory operation.
	// prepare traversal
	uvec2 stack[STACK_SIZE];
	uint hitAddr, stackPtr = 0;
	vec2 uv;
	float tmax = t;
	const uint octinv4 = (7 - ((D.x < 0 ? 4 : 0) | (D.y < 0 ? 2 : 0) | (D.z < 0 ? 1 : 0))) * 0x1010101;
	uvec2 ngroup = uvec2( 0, 0x80000000u ), tgroup = uvec2( 0 );
	do
	{
		COUNT( statSteps++ ); // tinybvh's steps++
		if (ngroup.y > 0x00FFFFFF)
		{
			const uint hits = ngroup.y, imask = ngroup.y;
			const uint child_bit_index = bfind( hits );
			const uint child_node_base_index = ngroup.x;
			ngroup.y &= ~(1 << child_bit_index);
			if (ngroup.y > 0x00FFFFFF) { STACK_PUSH( ngroup ); }
			{
				const uint slot_index = (child_bit_index - 24) ^ (octinv4 & 255);
				const uint relative_index = popc( imask & ~(0xFFFFFFFF << slot_index) );
				const uint child_node_index = (child_node_base_index + relative_index) * 5;
				vec4 n0 = cwbvhNodes[child_node_index + 0], n1 = cwbvhNodes[child_node_index + 1];
				vec4 n2 = cwbvhNodes[child_node_index + 2], n3 = cwbvhNodes[child_node_index + 3];
				vec4 n4 = cwbvhNodes[child_node_index + 4];
				const int ex = as_char( n0.w, 0 ), ey = as_char( n0.w, 1 ), ez = as_char( n0.w, 2 );
				ngroup.x = floatBitsToUint( n1.x ), tgroup = uvec2( floatBitsToUint( n1.y ), 0 );
				uint hitmask = 0;
				const vec4 idir4 = vec4( intBitsToFloat( (ex + 127) << 23 ) * rD.x,
					intBitsToFloat( (ey + 127) << 23 ) * rD.y, intBitsToFloat( (ez + 127) << 23 ) * rD.z, 1 );
				const vec4 orig4 = (n0 - O) * rD;
				{	// first 4
					const uint meta4 = floatBitsToUint( n1.z ), is_inner4 = (meta4 & (meta4 << 1)) & 0x10101010;
					const uint inner_mask4 = sign_extend_s8x4( is_inner4 << 3 );
					const uint bit_index4 = (meta4 ^ (octinv4 & inner_mask4)) & 0x1F1F1F1F;
					const uint child_bits4 = (meta4 >> 5) & 0x07070707;
					const vec4 lox4 = as_uchar4_float4( rD.x < 0 ? n3.z : n2.x ), hix4 = as_uchar4_float4( rD.x < 0 ? n2.x : n3.z );
					const vec4 loy4 = as_uchar4_float4( rD.y < 0 ? n4.x : n2.z ), hiy4 = as_uchar4_float4( rD.y < 0 ? n2.z : n4.x );
					const vec4 loz4 = as_uchar4_float4( rD.z < 0 ? n4.z : n3.x ), hiz4 = as_uchar4_float4( rD.z < 0 ? n3.x : n4.z );
					{
						const vec4 tminx4 = lox4 * idir4.xxxx + orig4.xxxx, tmaxx4 = hix4 * idir4.xxxx + orig4.xxxx;
						const vec4 tminy4 = loy4 * idir4.yyyy + orig4.yyyy, tmaxy4 = hiy4 * idir4.yyyy + orig4.yyyy;
						const vec4 tminz4 = loz4 * idir4.zzzz + orig4.zzzz, tmaxz4 = hiz4 * idir4.zzzz + orig4.zzzz;
						const float cmina = max( max( max( tminx4.x, tminy4.x ), tminz4.x ), 0 );
						const float cmaxa = min( min( min( tmaxx4.x, tmaxy4.x ), tmaxz4.x ), tmax );
						const float cminb = max( max( max( tminx4.y, tminy4.y ), tminz4.y ), 0 );
						const float cmaxb = min( min( min( tmaxx4.y, tmaxy4.y ), tmaxz4.y ), tmax );
						if (cmina <= cmaxa) UPDATE_HITMASK;
						if (cminb <= cmaxb) UPDATE_HITMASK1;
						const float cminc = max( max( max( tminx4.z, tminy4.z ), tminz4.z ), 0 );
						const float cmaxc = min( min( min( tmaxx4.z, tmaxy4.z ), tmaxz4.z ), tmax );
						const float cmind = max( max( max( tminx4.w, tminy4.w ), tminz4.w ), 0 );
						const float cmaxd = min( min( min( tmaxx4.w, tmaxy4.w ), tmaxz4.w ), tmax );
						if (cminc <= cmaxc) UPDATE_HITMASK2;
						if (cmind <= cmaxd) UPDATE_HITMASK3;
					}
				}
				{	// second 4
					const uint meta4 = floatBitsToUint( n1.w ), is_inner4 = (meta4 & (meta4 << 1)) & 0x10101010;
					const uint inner_mask4 = sign_extend_s8x4( is_inner4 << 3 );
					const uint bit_index4 = (meta4 ^ (octinv4 & inner_mask4)) & 0x1F1F1F1F;
					const uint child_bits4 = (meta4 >> 5) & 0x07070707;
					const vec4 lox4 = as_uchar4_float4( rD.x < 0 ? n3.w : n2.y ), hix4 = as_uchar4_float4( rD.x < 0 ? n2.y : n3.w );
					const vec4 loy4 = as_uchar4_float4( rD.y < 0 ? n4.y : n2.w ), hiy4 = as_uchar4_float4( rD.y < 0 ? n2.w : n4.y );
					const vec4 loz4 = as_uchar4_float4( rD.z < 0 ? n4.w : n3.y ), hiz4 = as_uchar4_float4( rD.z < 0 ? n3.y : n4.w );
					{
						const vec4 tminx4 = lox4 * idir4.xxxx + orig4.xxxx, tmaxx4 = hix4 * idir4.xxxx + orig4.xxxx;
						const vec4 tminy4 = loy4 * idir4.yyyy + orig4.yyyy, tmaxy4 = hiy4 * idir4.yyyy + orig4.yyyy;
						const vec4 tminz4 = loz4 * idir4.zzzz + orig4.zzzz, tmaxz4 = hiz4 * idir4.zzzz + orig4.zzzz;
						const float cmina = max( max( max( tminx4.x, tminy4.x ), tminz4.x ), 0 );
						const float cmaxa = min( min( min( tmaxx4.x, tmaxy4.x ), tmaxz4.x ), tmax );
						const float cminb = max( max( max( tminx4.y, tminy4.y ), tminz4.y ), 0 );
						const float cmaxb = min( min( min( tmaxx4.y, tmaxy4.y ), tmaxz4.y ), tmax );
						if (cmina <= cmaxa) UPDATE_HITMASK0;
						if (cminb <= cmaxb) UPDATE_HITMASK1;
						const float cminc = max( max( max( tminx4.z, tminy4.z ), tminz4.z ), 0 );
						const float cmaxc = min( min( min( tmaxx4.z, tmaxy4.z ), tmaxz4.z ), tmax );
						const float cmind = max( max( max( tminx4.w, tminy4.w ), tminz4.w ), 0 );
						const float cmaxd = min( min( min( tmaxx4.w, tmaxy4.w ), tmaxz4.w ), tmax );
						if (cminc <= cmaxc) UPDATE_HITMASK2;
						if (cmind <= cmaxd) UPDATE_HITMASK3;
					}
				}
				ngroup.y = (hitmask & 0xFF000000) | (floatBitsToUint( n0.w ) >> 24), tgroup.y = hitmask & 0x00FFFFFF;
			}
		}
		else tgroup = ngroup, ngroup = uvec2( 0 );
		while (tgroup.y != 0)
		{
			COUNT( statTests++ );
			// Möller-Trumbore intersection; triangles are stored as 3x16 bytes,
			// with the original primitive index in the (otherwise unused) w
			// component of vertex 0. iquilezles.org version.
			const int triangleIndex = int( bfind( tgroup.y ) ); const uint triAddr = tgroup.x + triangleIndex * 3;
			const vec3 e1 = cwbvhTris[triAddr].xyz;
			const vec3 e2 = cwbvhTris[triAddr + 1].xyz;
			const vec4 v0 = cwbvhTris[triAddr + 2];
			tgroup.y -= 1 << triangleIndex;
			const vec3 r = cross( D.xyz, e1 );
			const float a = dot( e2, r );
			const float f = 1 / a;
			const vec3 s = O.xyz - v0.xyz;
			const float u = f * dot( s, r );
			const vec3 q = cross( s, e2 );
			const float v = f * dot( D.xyz, q );
			if (u < 0 || v < 0 || u + v > 1) continue;
			const float d = f * dot( e1, q );
			if (d <= 0.0f || d >= tmax) continue;
			uv = vec2( u, v ), tmax = d;
			hitAddr = floatBitsToUint( v0.w );
		}
		if (ngroup.y <= 0x00FFFFFF)
		{
			if (stackPtr > 0) { STACK_POP( ngroup ); } else
			{
				hit = vec4( tmax, uv.x, uv.y, uintBitsToFloat( hitAddr ) );
				break;
			}
		}
	} while (true);
	return hit;
}

// batch_cwbvh, with the ray from vkmc's buffer: O.w = 1, D.w = 0, rD.w = 1 as the SIMD_AABBTEST path sets them,
// rD = tinybvh_safercp( D ) as tinybvh's Ray constructor computes it on the host.
float safercp( const float x ) { return x > 1e-12f || x < -1e-12f ? 1.0f / x : x >= 0 ? kTinybvhFar : -kTinybvhFar; }

void main()
{
	const uint threadId = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
	if (threadId >= pc.pathCount) return;
	const TestRay r = rayData.ray[threadId];
	const vec4 O4 = vec4( r.origin.xyz, 1 );
	const vec4 D4 = vec4( r.direction.xyz, 0 );
	const vec4 rD4 = vec4( safercp( D4.x ), safercp( D4.y ), safercp( D4.z ), 1 );
	result.hit[threadId] = traverse_cwbvh( O4, D4, rD4, kTinybvhFar );
	COUNT( walkStats[threadId] = uvec2( statSteps, statTests ) );
}
