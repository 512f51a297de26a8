/* The NREL 5-MW baseline controller (Jonkman et al. 2009, NREL/TP-500-38060,
 * chapter 7) as a Bladed-style DISCON library: variable-speed generator torque
 * in regions 1, 1 1/2, 2, 2 1/2 and 3, and gain-scheduled PI collective pitch,
 * with the report's constants. C99, no allocation, state in statics (one
 * turbine per loaded library, as DISCON libraries are). Records: see
 * runtime/include/yamsc/discon.hpp. */
#include <math.h>
#include <string.h>

#if defined(_WIN32)
#define YAMSC_DISCON_EXPORT __declspec(dllexport)
#else
#define YAMSC_DISCON_EXPORT __attribute__((visibility("default")))
#endif

/* Constants of the report (table 7-1 and DISCON.f90 of the baseline). */
static const double CornerFreq = 1.570796;  /* generator speed filter corner [rad/s] (0.25 Hz) */
static const double PC_DT = 0.00125;        /* pitch controller step [s] */
static const double PC_KI = 0.008068634;    /* integral gain at zero pitch [s] */
static const double PC_KK = 0.1099965;      /* pitch where the gains have halved [rad] */
static const double PC_KP = 0.01882681;     /* proportional gain at zero pitch [s] */
static const double PC_MaxPit = 1.570796;   /* [rad] */
static const double PC_MaxRat = 0.1396263;  /* pitch rate limit [rad/s] (8 deg/s) */
static const double PC_MinPit = 0.0;        /* [rad] */
static const double PC_RefSpd = 122.9096;   /* rated generator speed [rad/s] (1173.7 rpm) */
static const double VS_CtInSp = 70.16224;   /* cut-in generator speed [rad/s] (670 rpm) */
static const double VS_DT = 0.00125;        /* torque controller step [s] */
static const double VS_MaxRat = 15000.0;    /* torque rate limit [N m/s] */
static const double VS_MaxTq = 47402.91;    /* [N m] */
static const double VS_Rgn2K = 2.332287;    /* region-2 constant [N m/(rad/s)^2] */
static const double VS_Rgn2Sp = 91.21091;   /* start of region 2 [rad/s] */
static const double VS_Rgn3MP = 0.01745329; /* pitch above which region 3 holds [rad] (1 deg) */
static const double VS_RtGnSp = 121.6805;   /* generator speed at rated torque [rad/s] */
static const double VS_RtPwr = 5296610.0;   /* rated mechanical power [W] (5 MW / 94.4 %) */
static const double VS_SlPc = 10.0;         /* region 2 1/2 synchronous slip [%] */

static double GenSpeedF, IntSpdErr, LastGenTrq, LastTime, LastTimePC, LastTimeVS, PitCom;

static double clamp(double x, double lo, double hi) {
    return x < lo ? lo : (x > hi ? hi : x);
}

static void message(char* avcMSG, int size, const char* text) {
    if (size > 0) {
        strncpy(avcMSG, text, (size_t)size - 1);
        avcMSG[size - 1] = '\0';
    }
}

YAMSC_DISCON_EXPORT void DISCON(float* avrSWAP, int* aviFAIL, const char* accINFILE,
                                char* avcOUTNAME, char* avcMSG);

void DISCON(float* avrSWAP, int* aviFAIL, const char* accINFILE, char* avcOUTNAME, char* avcMSG) {
    const int iStatus = (int)lround(avrSWAP[0]);
    const double Time = avrSWAP[1];
    const double BlPitch = avrSWAP[3];
    const double GenSpeed = avrSWAP[19];
    const int msg_size = (int)lround(avrSWAP[48]);
    const double VS_SySp = VS_RtGnSp / (1.0 + 0.01 * VS_SlPc);
    const double VS_Slope15 = (VS_Rgn2K * VS_Rgn2Sp * VS_Rgn2Sp) / (VS_Rgn2Sp - VS_CtInSp);
    const double VS_Slope25 = (VS_RtPwr / VS_RtGnSp) / (VS_RtGnSp - VS_SySp);
    const double VS_TrGnSp =
        (VS_Slope25 - sqrt(VS_Slope25 * (VS_Slope25 - 4.0 * VS_Rgn2K * VS_SySp))) /
        (2.0 * VS_Rgn2K);
    (void)accINFILE;
    (void)avcOUTNAME;
    *aviFAIL = 0;
    if (iStatus < 0) return; /* the last call: nothing to close */
    if (iStatus == 0) {
        double GK;
        if (VS_Slope25 * (VS_Slope25 - 4.0 * VS_Rgn2K * VS_SySp) < 0.0) {
            *aviFAIL = -1;
            message(avcMSG, msg_size, "VS_Rgn2K too large for the region 2 1/2 line");
            return;
        }
        GenSpeedF = GenSpeed;
        PitCom = BlPitch;
        GK = 1.0 / (1.0 + PitCom / PC_KK);
        IntSpdErr = PitCom / (GK * PC_KI);
        LastTime = Time;
        LastTimePC = Time - PC_DT;
        LastTimeVS = Time - VS_DT;
        LastGenTrq = avrSWAP[22];
    }
    {
        /* the generator speed through a first-order low-pass filter */
        const double Alpha = exp((LastTime - Time) * CornerFreq);
        GenSpeedF = (1.0 - Alpha) * GenSpeed + Alpha * GenSpeedF;
    }
    if (Time - LastTimeVS >= VS_DT - 1e-9) {
        double GenTrq, TrqRate;
        if (GenSpeedF >= VS_RtGnSp || PitCom >= VS_Rgn3MP)
            GenTrq = VS_RtPwr / GenSpeedF; /* region 3: constant power */
        else if (GenSpeedF <= VS_CtInSp)
            GenTrq = 0.0; /* region 1 */
        else if (GenSpeedF < VS_Rgn2Sp)
            GenTrq = VS_Slope15 * (GenSpeedF - VS_CtInSp); /* region 1 1/2 */
        else if (GenSpeedF < VS_TrGnSp)
            GenTrq = VS_Rgn2K * GenSpeedF * GenSpeedF; /* region 2: optimal tip-speed ratio */
        else
            GenTrq = VS_Slope25 * (GenSpeedF - VS_SySp); /* region 2 1/2 */
        GenTrq = GenTrq < VS_MaxTq ? GenTrq : VS_MaxTq;
        TrqRate = clamp((GenTrq - LastGenTrq) / (Time - LastTimeVS), -VS_MaxRat, VS_MaxRat);
        GenTrq = LastGenTrq + TrqRate * (Time - LastTimeVS);
        LastTimeVS = Time;
        LastGenTrq = GenTrq;
    }
    if (Time - LastTimePC >= PC_DT - 1e-9) {
        const double ElapTime = Time - LastTimePC;
        const double GK = 1.0 / (1.0 + PitCom / PC_KK); /* gain scheduling */
        const double SpdErr = GenSpeedF - PC_RefSpd;
        double PitComT, PitRate;
        IntSpdErr = clamp(IntSpdErr + SpdErr * ElapTime, PC_MinPit / (GK * PC_KI),
                          PC_MaxPit / (GK * PC_KI));
        PitComT = clamp(GK * PC_KP * SpdErr + GK * PC_KI * IntSpdErr, PC_MinPit, PC_MaxPit);
        PitRate = clamp((PitComT - BlPitch) / ElapTime, -PC_MaxRat, PC_MaxRat);
        PitCom = clamp(BlPitch + PitRate * ElapTime, PC_MinPit, PC_MaxPit);
        LastTimePC = Time;
    }
    LastTime = Time;
    avrSWAP[34] = 1.0f;          /* generator contactor: main */
    avrSWAP[35] = 0.0f;          /* shaft brake off */
    avrSWAP[40] = 0.0f;          /* yaw actuator torque */
    avrSWAP[41] = (float)PitCom; /* individual pitch demands */
    avrSWAP[42] = (float)PitCom;
    avrSWAP[43] = (float)PitCom;
    avrSWAP[44] = (float)PitCom; /* collective pitch demand */
    avrSWAP[45] = 0.0f;          /* pitch rate demand */
    avrSWAP[46] = (float)LastGenTrq;
    avrSWAP[47] = 0.0f; /* yaw rate demand */
    avrSWAP[54] = 0.0f; /* pitch override: yes */
    avrSWAP[55] = 0.0f; /* torque override: yes */
    avrSWAP[64] = 0.0f; /* no logging channels */
}
