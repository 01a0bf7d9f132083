/*  oro events benchmark: latency of pushed events and cost of changes
    with many watchers registered, over the socket.

        swipl bench/bench_events.pl [--samples=200] [--levels=1,100,1000]

    (default levels: 1,100,1000,1000-other; W-other puts the W watchers on
    another predicate)

    It starts the real server (server/oro_server.pl --port=0) as a child
    process and, on one connection, for each level W:

      - resets the server, registers W NEW_INSTANCE watchers with
        distinct patterns `?o isOn shelf_I` (all on the predicate the
        measured changes touch, so every change re-evaluates them all),
        then the measured watcher `?o isOn bench_table`, last, so its
        event comes after all the others have been evaluated;
      - event latency: time from sending `add [objN isOn bench_table]`
        (a new object each sample) to receiving the pushed event
        `["objN"]` (median, p99, and the median of the part after the
        `ok` reply arrived); a sample whose event does not come within
        5 s (or comes with another content) counts as missed;
      - a level W-other registers the W watchers on another predicate
        (`?o isIn box_I`): the changes do not touch them (index by
        predicate);
      - cost of a plain add: round trip of `add` on a predicate no
        watcher uses (`objN hasColor red`) and on the watched one
        (`objN isOn floor`, firing nothing), with W watchers and with
        none (level 0).

    Between phases a registration of an already registered watcher
    serves as a barrier: it is answered once the watcher thread has
    processed every change before it.
*/

:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(samples, samples, nonneg).
opt_type(levels, levels, term).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(samples(Samples), Options, 200),
    bench_list_option(levels(Levels), Options, [1, 100, 1000, 1000-other]),
    bench_machine,
    bench_with_server([], Port, _, bench(Port, Samples, Levels)).

%   call_ok(+Conn, +Method, +Params[, -Value]): a request whose next
%   message must be its `ok` (no event is pending when it is used),
%   within 30 s.

call_ok(Conn, Method, Params, Value) :-
    bench_call(Conn, Method, Params, Value, 30).

call_ok(Conn, Method, Params) :-
    bench_call(Conn, Method, Params, _, 30).

		 /*******************************
		 *            LEVELS            *
		 *******************************/

bench(Port, Samples, Levels) :-
    bench_with_connection(
        Port, Conn,
        ( format("~n~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
                 [watchers, 'register', 'event median', 'event p99',
                  'after ok', missed, 'add unwatched', 'add watched']),
          level(Conn, 0, Samples),
          forall(member(W, Levels), level(Conn, W, Samples))
        )).

level(Conn, Level, Samples) :-
    (   Level = W-other
    ->  Shelf = "[?o isIn box_~d]"
    ;   W = Level,
        Shelf = "[?o isOn shelf_~d]"
    ),
    call_ok(Conn, reset, []),
    register_shelves(Conn, W, Shelf, RegTimes),
    (   W > 0
    ->  measured_pattern(Pattern),
        call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern], Id),
        latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed),
        barrier(Conn)
    ;   Latencies = [],
        AfterOk = [],
        Missed = '-'
    ),
    add_times(Conn, W, unwatched, Samples, Unwatched),
    barrier(Conn),
    add_times(Conn, W, watched, Samples, Watched),
    barrier(Conn),
    row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched).

measured_pattern("[?o isOn bench_table]").

register_shelves(Conn, W, Shelf, Times) :-
    findall(T,
            ( between(1, W, I),
              format(string(P), Shelf, [I]),
              bench_time(call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", P]), T)
            ), Times).

%   barrier(+Conn): returns once every change sent before has been
%   processed by the watcher thread (a registration is queued behind
%   them; this one is a duplicate, so it changes nothing).

barrier(Conn) :-
    measured_pattern(Pattern),
    call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern]).

latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed) :-
    findall(Result,
            ( between(1, Samples, I),
              latency(Conn, Id, W, I, Result)
            ), Results),
    findall(L, member(L-_, Results), Latencies),
    findall(A, member(_-A, Results), AfterOk),
    exclude(is_pair, Results, MissedList),
    length(MissedList, Missed).

is_pair(_-_).

latency(Conn, Id, W, I, Result) :-
    format(atom(Obj), "obj_~d_~d", [W, I]),
    format(string(Stmt), "[~w isOn bench_table]", [Obj]),
    format(string(Expected), "[\"~w\"]", [Obj]),
    get_time(T0),
    bench_send(Conn, add, [Stmt]),
    bench_receive(Conn, Reply, 30),
    (   Reply = ok(_)
    ->  get_time(TOk),
        bench_receive(Conn, Event, 5),
        get_time(T1),
        (   Event = event(Id, Expected)
        ->  Latency is (T1 - T0) * 1.0e6,
            After is (T1 - TOk) * 1.0e6,
            Result = Latency-After
        ;   Result = missed(Event)
        )
    ;   Result = missed(Reply)
    ).

add_times(Conn, W, Kind, Samples, Times) :-
    findall(T,
            ( between(1, Samples, I),
              add_statement(Kind, W, I, Stmt),
              bench_time(call_ok(Conn, add, [Stmt]), T)
            ), Times).

add_statement(unwatched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d hasColor red]", [W, I]).
add_statement(watched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d isOn floor]", [W, I]).

		 /*******************************
		 *            REPORT            *
		 *******************************/

row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched) :-
    median_text(RegTimes, Reg),
    bench_summary(Latencies, LMedian, LP99),
    bench_micros(LMedian, LMed),
    bench_micros(LP99, LP),
    median_text(AfterOk, AMed),
    median_text(Unwatched, UMed),
    median_text(Watched, WMed),
    (   Level = W-other
    ->  format(string(Label), "~d (isIn)", [W])
    ;   format(string(Label), "~d", [Level])
    ),
    format("~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
           [Label, Reg, LMed, LP, AMed, Missed, UMed, WMed]),
    flush_output.

%   median_text(+Times, -Text): the median of Times, "-" if there are
%   none.

median_text(Times, Text) :-
    bench_summary(Times, Median, _),
    bench_micros(Median, Text).
