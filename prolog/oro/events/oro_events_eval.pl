:- module(oro_events_eval,
          [ oro_events_start/0,
            call_watcher/1,             % +Request
            call_watcher/2,             % +Request, -Reply
            call_watcher/3              % +Request, -Reply, +Options
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(assoc)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(uuid)).
:- use_module(library(ordsets)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_query)).
:- use_module(library(oro/events/oro_events_registry)).
:- use_module(library(oro/events/oro_events_monitor)).
:- use_module(library(oro/events/oro_events_delivery)).

/** <module> Events: the watcher thread and the evaluation of watchers

The watcher thread (alias `oro_watcher`) and its queue (alias
`oro_watcher_queue`), which this module creates and owns: it takes the
changes the monitor (oro_events_monitor) queues, in commit order, and
the requests of the other threads (call_watcher/3: registration,
clearing, reset, sync); it evaluates, inside the snapshot of each
change, the watchers the change may affect (CHANGES), from the
change's triples where that is sound (INCREMENTAL, see the module doc
of oro_events), and hands their firings to delivery
(oro_events_delivery).  When idle it compiles ahead the shared schema
tables of the models.  It owns the schema tables it compiled for each
model (model_schema/2) and the mutex `oro_events` (starting the thread
and the monitor).
*/

:- dynamic
    model_schema/2.                 % Model, Key (the watcher thread's)

%   The seeds a watcher may be solved with in one change (a bound of
%   incremental evaluation).

max_seeds(2000).

		 /*******************************
		 *            START             *
		 *******************************/

%!  oro_events_start is det.
%
%   Start the watcher thread and the store monitor, if not running.

oro_events_start :-
    with_mutex(oro_events,
               (   watcher_running
               ->  true
               ;   message_queue_create(_, [alias(oro_watcher_queue)]),
                   thread_create(watcher_start, _,
                                 [alias(oro_watcher), detached(false)]),
                   monitor_mask(Mask),
                   rdf_monitor(oro_events_monitor:monitor, Mask)
               )).

monitor_mask([-all, +assert, +retract, +update, +transaction]).

%   A store rebuild (oro_store_rebuild/0) must not reset rdf_db while
%   changes wait in the watcher's queue with their snapshots; the
%   watchers must not see the store emptied and filled again (with the
%   same triples: their state stays right).

%   Every schema change, once over, sends the watcher thread a message,
%   after which it compiles ahead (warm_while_idle/0).  The messages of
%   the changes' triples do not do: a write's commit sends them before
%   the write bumps the schema generation for the last time, and a
%   rolled-back write, an ontology load or a reset send none.

:- multifile oro_store:schema_hook/1.

oro_store:schema_hook(changed) :-
    setting(oro_events:warm_schemas, true),
    watcher_running,
    thread_send_message(oro_watcher_queue, schema_changed).

:- multifile oro_store:rebuild_hook/1.

oro_store:rebuild_hook(blocked(Deadline)) :-
    watcher_running,
    get_time(Now),
    Timeout is max(0, Deadline - Now),
    \+ call_watcher(sync, true, [timeout(Timeout)]).
oro_store:rebuild_hook(suspend) :-
    (   watcher_running
    ->  rdf_monitor(oro_events_monitor:monitor, [-all])
    ;   true
    ).
oro_store:rebuild_hook(resume) :-
    (   watcher_running
    ->  monitor_mask(Mask),
        rdf_monitor(oro_events_monitor:monitor, Mask)
    ;   true
    ).

watcher_running :-
    catch(thread_property(oro_watcher, status(running)), _, fail).

%!  call_watcher(+Request) is det.
%!  call_watcher(+Request, -Reply) is det.
%!  call_watcher(+Request, -Reply, +Options) is semidet.
%
%   Send Request to the watcher thread (started if need be) and wait
%   for its Reply; an error it raised is raised again here.  With
%   Options, fails if the reply does not come within their
%   timeout(Seconds) (it is then left in the caller's queue, where no
%   later call looks for its tag).

call_watcher(Request) :-
    call_watcher(Request, true).

call_watcher(Request, Reply) :-
    call_watcher(Request, Reply, []).

call_watcher(Request, Reply, Options) :-
    oro_events_start,
    thread_self(Me),
    forget_late_replies(Me),
    gensym(oro_reply_, Tag),
    thread_send_message(oro_watcher_queue, call(Request, Me, Tag)),
    (   thread_get_message(Me, reply(Tag, Result), Options)
    ->  true
    ;   late_tags(Late),
        nb_setval(oro_events_late, [Tag|Late]),
        fail
    ),
    (   Result = error(E)
    ->  throw(E)
    ;   Result = Reply
    ).

%   forget_late_replies(+Me): take from the queue of the calling thread
%   the replies that came after their call_watcher/3 gave up waiting
%   (as they come; the others are looked for again at the next call).

forget_late_replies(Me) :-
    late_tags(Late),
    (   Late == []
    ->  true
    ;   exclude(late_reply_taken(Me), Late, Left),
        nb_setval(oro_events_late, Left)
    ).

late_reply_taken(Me, Tag) :-
    thread_get_message(Me, reply(Tag, _), [timeout(0)]).

%   late_tags(-Tags): the tags of the calling thread's replies still
%   to come after their call gave up (a global variable of the thread).

late_tags(Tags) :-
    (   nb_current(oro_events_late, Tags0)
    ->  Tags = Tags0
    ;   Tags = []
    ).

		 /*******************************
		 *        WATCHER THREAD        *
		 *******************************/

%   The watcher thread passes a closed rebuild gate (oro_store_read/1):
%   a rebuild waits for it to process every change, and the writes of
%   its in-watcher callbacks (agent models) are part of that.

watcher_start :-
    oro_store_gate_exempt,
    watcher_loop.

watcher_loop :-
    thread_get_message(oro_watcher_queue, Message),
    catch(( handle(Message),
            collect_dropped,
            warm_while_idle
          ),
          E, handle_error(E)),
    watcher_loop.

%   warm_while_idle: while no message waits, compile the shared schema
%   tables of the models that have none for the current generation,
%   one model at a time (`myself` first).  It stops when every model
%   has them, and when a compilation did not give a model current
%   tables (a schema change started meanwhile): once that change is
%   over, its schema_changed message (see below) starts it again, so a
%   long schema-changing write is not met with compilation after
%   compilation.  It reads the store through the rebuild gate, without
%   waiting (oro_store_try_read/1): a store rebuild must not reset
%   rdf_db under it, and sends schema_changed once it is over.

warm_while_idle :-
    (   setting(oro_events:warm_schemas, true),
        \+ thread_peek_message(oro_watcher_queue, _),
        cold_model(Model)
    ->  (   oro_store_try_read(oro_shared_schema(Model, _)),
            oro_compiled_schema(Model, _)
        ->  debug(oro(events), 'Schema tables of ~q compiled ahead', [Model]),
            warm_while_idle
        ;   true
        )
    ;   true
    ).

cold_model(Model) :-
    (   Model = myself,
        oro_model(myself)
    ;   oro_model(Model),
        Model \== myself
    ),
    \+ oro_compiled_schema(Model, _),
    !.

%   How many watchers there are is counted (the flag
%   oro_events_watchers) by this thread, which alone has watcher/5
%   asserted and retracted (oro_events_registry): the writers' monitor
%   asks for every triple (watching/0).  Asking watcher/5 itself would cost time in
%   proportion to the watchers dropped so far: SWI-Prolog keeps a
%   retracted clause, which lookups step over, until its clause garbage
%   collector runs, and it looks past the first clause for another one.
%   The collector starts by itself only when the retracted clauses
%   weigh enough against all the program's clauses, which a store's
%   name index makes large.  So the watcher thread runs the collector
%   itself once max_dropped/1 watchers were dropped since it last did.
%   What the dropped watchers cost before (a scratch script, and
%   bench_full's adds with two requests in flight, which it measures
%   after registering and clearing 2,000 watchers) is in
%   the history of bench/RESULTS.md (git log), "Dropped watchers left work behind".

max_dropped(32).

collect_dropped :-
    flag(oro_events_dropped, Dropped, Dropped),
    (   max_dropped(Max),
        Dropped >= Max
    ->  flag(oro_events_dropped, _, 0),
        garbage_collect_clauses
    ;   true
    ).

%   An error is reported and the thread goes on with the next message;
%   an abort (the process halting) ends it quietly.

handle_error(E) :-
    rethrow_abort(E),
    print_message(error, E).

rethrow_abort(E) :-
    (   ( E == '$aborted' ; E = unwind(_) )
    ->  throw(E)
    ;   true
    ).

handle(change(Snapshot, Touched, Schema, Delta)) :-
    call_cleanup(process_change(Snapshot, Touched, Schema, Delta),
                 ( rdf_delete_snapshot(Snapshot),
                   (   Schema == true
                   ->  flag(oro_events_pending, N, N-1)
                   ;   true
                   )
                 )),
    run_direct_deliveries.
handle(warm(Model)) :-                 % compiled unless already done
    ignore(oro_store_try_read(oro_shared_schema(Model, _))).
handle(schema_changed).                 % warm_while_idle/0 follows
handle(call(Request, Thread, Tag)) :-
    (   catch(request(Request, Result0), E, (Result0 = error(E)))
    ->  Result = Result0
    ;   Result = error(failed(Request))
    ),
    catch(thread_send_message(Thread, reply(Tag, Result)),
          error(existence_error(thread, _), _),
          true).                        % the caller is gone

request(sync, true).
request(reset, stop(Stops)) :-
    drop_all_watchers,
    forall(retract(model_schema(_, Key)), oro_drop_schema(Key)),
    claim_callback_subscribers(Stops).
request(register(Model, Registry, Spec, Query, Subscriber, Snapshot), id(Id)) :-
    call_cleanup(register(Model, Registry, Spec, Query, Subscriber,
                          Snapshot, Id),
                 ( rdf_delete_snapshot(Snapshot),
                   flag(oro_events_pending, N, N-1)
                 )).
request(clear(Model, Registry), true) :-
    forall(watcher(Id, Model, Registry, _, _), drop_watcher(Id)).
request(clear_one(Model, Registry, Id), true) :-
    (   watcher(Id, Model, Registry, _, _)
    ->  drop_watcher(Id)
    ;   existence_error(event, Id)
    ).
request(unsubscribe(Subscriber), true) :-
    unsubscribe(Subscriber).

register(_, _, _, _, Subscriber, _, _) :-
    \+ subscriber(Subscriber, _, _, _),
    !,
    existence_error(oro_subscriber, Subscriber).    % destroyed meanwhile
register(Model, Registry, Spec, _, Subscriber, _, Id) :-
    join_variant(Model, Registry, Spec, Subscriber, Id),
    !,
    note_callback(Id, Subscriber).
register(Model, Registry, Spec, Query, Subscriber, Snapshot, Id) :-
    uuid(Id, [version(4)]),
    rdf_transaction(ensure_schemas([Model]), oro(events), [snapshot(Snapshot)]),
    in_snapshot(Snapshot, [Model],
                ( initial_state(Spec, Model, Query, State, Values),
                  watcher_index(Spec, Model, Query, State, Index)
                )),
    add_watcher(Id, Model, Registry, Spec, Query, State, Values, Index,
                Subscriber),
    note_callback(Id, Subscriber),
    debug(oro(events), 'Watcher ~w: ~q', [Id, Spec]).

%   The initial state: fact_checking watchers start `unknown` (false)
%   and are not evaluated (ORO-SPEC §7.3); the others remember their
%   current values.

initial_state(spec(fact_checking, _, _, _), _, _, unknown, []) :- !.
initial_state(_, Model, Query, values, Values) :-
    query_values(Model, Query, Values).

%   in_snapshot(+Snapshot, +Models, :Goal): run Goal in the snapshot,
%   with the schemas the watcher thread compiled for Models.

in_snapshot(Snapshot, Models, Goal) :-
    rdf_transaction(with_schemas(Models, Goal), oro(events), [snapshot(Snapshot)]).

with_schemas(Models, Goal) :-
    findall(M-K, ( member(M, Models), model_schema(M, K) ), Keys),
    oro_with_schemas(Keys, Goal).

		 /*******************************
		 *           CHANGES            *
		 *******************************/

process_change(Snapshot, Touched, Schema, Delta) :-
    setting(oro_events:index, Index),
    (   (   Schema == true
        ;   Index == false                  % the reference mode
        )
    ->  forget_schemas(Touched)
    ;   true
    ),
    affected_models(Touched, Models),
    (   Models == []
    ->  true
    ;   setting(oro_events:incremental, Incremental),
        rdf_transaction(change_in_snapshot(Models, Touched, Schema, Delta,
                                           Incremental-Index),
                        oro(events), [snapshot(Snapshot)])
    ).

%   After a schema change, the schemas the watcher thread compiled for
%   the models it touched are stale: they are compiled again, in the
%   snapshot of the next change or registration that needs them.

forget_schemas(Touched) :-
    (   memberchk('$all'-_, Touched)
    ->  forall(retract(model_schema(_, Key)), oro_drop_schema(Key))
    ;   forall(( member(M-_, Touched),
                 retract(model_schema(M, Key))
               ),
               oro_drop_schema(Key))
    ).

affected_models(Touched, Models) :-
    (   memberchk('$all'-_, Touched)
    ->  findall(M, watcher(_, M, _, _, _), Models0)
    ;   findall(M, ( member(M-_, Touched),
                     once(watcher(_, M, _, _, _))
                   ), Models0)
    ),
    sort(Models0, Models).

change_in_snapshot(Models, Touched, Schema, Delta, How) :-
    ensure_schemas(Models),
    with_schemas(Models,
                 forall(member(Model, Models),
                        evaluate_model(Model, Touched, Schema, Delta, How))).

ensure_schemas(Models) :-
    forall(( member(M, Models),
             \+ model_schema(M, _)
           ),
           ( oro_compile_schema(M, Key),
             assertz(model_schema(M, Key))
           )).

%   evaluate_model(+Model, +Touched, +Schema, +Delta,
%                  +Incremental-Index): evaluate the watchers of Model
%   the change may affect, in registration order: all of them after a
%   schema change, or in the reference mode (Index `false`).  Mode is
%   `full` or delta(Added, Removed, Same), the triples of the change in
%   Model.

evaluate_model(Model, Touched, Schema, Delta, Incremental-Index) :-
    (   (   Schema == true
        ;   Index == false
        )
    ->  findall(Id, watcher(Id, Model, _, _, _), Ids0),
        Mode = full
    ;   Incremental == true,
        Delta \== full,
        \+ memberchk('$all'-_, Touched)
    ->  model_delta(Model, Delta, Added, Removed, Same),
        Mode = delta(Added, Removed, Same),
        triggered_watchers(Model, Added, Removed, Same, Ids0)
    ;   findall(Id, ( watcher_dep(Model, any, Id)
                    ; ( member(Model-P, Touched)
                      ; member('$all'-P, Touched)
                      ),
                      watcher_dep(Model, P, Id)
                    ), Ids0),
        Mode = full
    ),
    by_registration(Ids0, Ids),
    debug(oro(events), 'Change of ~q: ~q', [Model, watchers(Ids)]),
    forall(member(Id, Ids), guarded_evaluation(Id, Mode, Schema)).

%   guarded_evaluation(+Id, +Mode, +Schema): evaluate_watcher/3, for
%   one watcher alone.  A watcher whose evaluation raises an error (its
%   query ran over the `oro_query:time_limit`, say: a pattern joining
%   unrelated variables over a large store) is dropped, and the server
%   says so in its log; the other watchers of the change are evaluated
%   as usual.  Kept, it would raise again at each change, and hold up
%   every other subscriber's events for as long each time.

guarded_evaluation(Id, Mode, Schema) :-
    catch(evaluate_watcher(Id, Mode, Schema), E,
          watcher_failed(Id, E)).

watcher_failed(Id, E) :-
    rethrow_abort(E),
    print_message(warning, oro_watcher_dropped(Id)),
    print_message(warning, E),
    drop_watcher(Id).

:- multifile prolog:message//1.

prolog:message(oro_watcher_dropped(Id)) -->
    [ 'Event ~w dropped: its evaluation raised the error below'-[Id] ].

%   model_delta(+Model, +Delta, -Added, -Removed, -Same): the triples
%   of Delta added to and removed from Model, as ordered sets of
%   t(S, P, O), and an assoc from their resources to their owl:sameAs
%   individuals (themselves included), looked up once a change.

model_delta(Model, Delta, Added, Removed, Same) :-
    findall(t(S, P, O), member(d(Model, add, S, P, O), Delta), Added0),
    sort(Added0, Added),
    findall(t(S, P, O), member(d(Model, del, S, P, O), Delta), Removed0),
    sort(Removed0, Removed),
    (   oro_has_same_individuals(Model)
    ->  findall(X, ( member(d(Model, _, S, _, O), Delta),
                     (   X = S
                     ;   X = O
                     ),
                     atom(X)
                   ), Resources0),
        sort(Resources0, Resources),
        findall(X-Ys, ( member(X, Resources),
                        findall(Y, oro_same_individual(Model, X, Y), Ys)
                      ), Pairs),
        list_to_assoc(Pairs, Same)
    ;   empty_assoc(Same)                   % each individual is itself only
    ).

%   triggered_watchers(+Model, +Added, +Removed, -Ids): the watchers
%   depending on any change, and those a trigger of a changed triple
%   names: by predicate alone, by a resource of the triple (or one of
%   its owl:sameAs individuals) or, for a type, by a super class.

triggered_watchers(Model, Added, Removed, Same, Ids) :-
    findall(Id, ( watcher_dep(Model, any, Id)
                ; ( member(t(S, P, O), Added)
                  ; member(t(S, P, O), Removed)
                  ),
                  triggered(Model, Same, S, P, O, Id)
                ), Ids).

triggered(Model, Same, S, P, O, Id) :-
    (   triple_anchor(Same, S, O, Anchor),
        trigger_key(Model, P, Anchor, Key),
        watcher_trigger(Key, Model, P, Anchor, Id)
    ;   rdf_equal(P, rdf:type),
        model_schema(Model, SchemaKey),
        class_watcher(SchemaKey, Model, O, Id)
    ;   chain_watcher(Model, Same, S, P, O, Id)
    ).

triple_anchor(_, _, _, none).
triple_anchor(Same, S, O, res(R)) :-
    (   X = S
    ;   X = O
    ),
    atom(X),
    same_individual(Same, X, R).

%   chain_watcher(+Model, +Same, +S, +P, +O, -Id): watcher Id has a
%   pattern through a transitive property T (Kind trans(_), see
%   item_anchor/5) whose constant end is among the resources a triple
%   `S P O`, P a dependency of T, can join to a new (or lost) instance:
%   what reaches S or O through T and what they reach, themselves and
%   their owl:sameAs individuals included (the ends chain_ends/8 seeds
%   from).  Such a watcher is anchored by chain(C), C its constant, and
%   by `chain`, which selects every one of them on P when the ends are
%   more than max_seeds/1 (as every change of P did before).  A lost
%   instance A T B used a removed triple: the first removed one on its
%   path, u-v, has A among what reaches u after the change, the last
%   one has B among what v reaches.

chain_watcher(Model, Same, S, P, O, Id) :-
    trigger_key(Model, P, chain, AnyKey),
    once(watcher_trigger(AnyKey, Model, P, chain, _)),
    chain_anchors(Model, Same, S, P, O, Anchors),
    length(Anchors, N),
    max_seeds(Max),
    (   N =< Max
    ->  member(C, Anchors),
        trigger_key(Model, P, chain(C), Key),
        watcher_trigger(Key, Model, P, chain(C), Id)
    ;   watcher_trigger(AnyKey, Model, P, chain, Id)
    ).

chain_anchors(Model, Same, S, P, O, Anchors) :-
    findall(C, ( oro_transitive_property(Model, T),
                 oro_pattern_dependencies(Model, [rdf(_, T, _)], TDeps),
                 ord_memberchk(P, TDeps),
                 (   X = S
                 ;   X = O
                 ),
                 atom(X),
                 (   same_individual(Same, X, C)
                 ;   oro_holds(Model, C, T, X)
                 ;   oro_holds(Model, X, T, C)
                 )
               ), Anchors0),
    sort(Anchors0, Anchors).

evaluate_watcher(Id, Mode, Schema) :-
    watcher(Id, Model, _, Spec, Query),
    watcher_state(Id, State0),
    !,
    outcome(Mode, Id, Spec, Model, Query, State0, Outcome),
    Spec = spec(Type, Trigger, _, _),
    apply_outcome(Outcome, Id, State0, State),
    firings(Type, Trigger, State0, Outcome, Contents, Remove),
    forall(member(Content, Contents), fire(Id, Content)),
    (   Remove == true
    ->  drop_watcher(Id)
    ;   \+ watcher(Id, _, _, _, _)
    ->  true                                % its subscribers were dropped
    ;   (   Schema == true
        ;   State0 == unknown
        )
    ->  watcher_index(Spec, Model, Query, State, Index),
        set_index(Id, Model, Index)
    ;   true
    ).
evaluate_watcher(_, _, _).                  % dropped meanwhile

%   outcome(+Mode, +Id, +Spec, +Model, +Query, +State0, -Outcome): the
%   new truth(Bool) of a fact_checking watcher, or diff(Added,
%   Removed) of the values of the others (ordered sets), evaluated
%   from the change's triples where the plan allows, else in full.

outcome(delta(Added, Removed, Same), Id, Spec, Model, Query, State0, Outcome) :-
    watcher_plan(Id, Plan),
    catch(delta_outcome(Plan, Spec, Id, Model-Same, Query, State0,
                        Added, Removed, Outcome0),
          oro_events_full, fail),
    !,
    debug(oro(events), 'Watcher ~w: from the change, ~q', [Id, Outcome0]),
    Outcome = Outcome0.
outcome(_, Id, Spec, Model, Query, _, Outcome) :-
    full_outcome(Spec, Id, Model, Query, Outcome),
    debug(oro(events), 'Watcher ~w: in full, ~q', [Id, Outcome]).

full_outcome(spec(fact_checking, _, _, _), _, Model, query(_, Triples), truth(Truth)) :-
    !,
    (   \+ \+ oro_solve(Model, Triples)
    ->  Truth = true
    ;   Truth = false
    ).
full_outcome(_, Id, Model, Query, diff(Added, Removed)) :-
    query_values(Model, Query, Now),
    findall(V, watcher_value(V, Id), Old0),
    sort(Old0, Old),
    ord_subtract(Now, Old, Added),
    ord_subtract(Old, Now, Removed).

query_values(Model, query(Template, Triples), Values) :-
    (   var(Template)
    ->  oro_find_values(Model, Template, Triples, Values)
    ;   Values = []
    ).

		 /*******************************
		 *         INCREMENTAL          *
		 *******************************/

%   delta_outcome(+Plan, +Spec, +Id, +Ctx, +Query, +State0, +Added,
%                 +Removed, -Outcome) is semidet.
%
%   The outcome of the change from its triples, in the new state; Ctx
%   is Model-Same, Same as made by model_delta/5.  Fails, or throws
%   oro_events_full, when the watcher must be evaluated in full.

delta_outcome(static, _, _, _, _, _, _, _, diff([], [])).
delta_outcome(items(Items), Spec, Id, Ctx, Query, State0, Added, Removed,
              Outcome) :-
    State0 \== unknown,
    concerned(Items, Added, AddPairs),
    concerned(Items, Removed, RemovePairs),
    (   Spec = spec(fact_checking, _, _, _)
    ->  truth_outcome(State0, Ctx, Query, AddPairs, RemovePairs, Outcome)
    ;   lost_values(RemovePairs, Id, Ctx, Query, Lost),
        new_values(AddPairs, Id, Ctx, Query, New),
        Outcome = diff(New, Lost)
    ).

%   concerned(+Items, +Triples, -Pairs): Item-Triple for each pattern
%   and changed triple whose predicate it depends on.

concerned(_, [], []) :-
    !.
concerned(Items, Triples, Pairs) :-
    findall(Item-t(S, P, O),
            ( member(t(S, P, O), Triples),
              member(Item, Items),
              item_depends(Item, P)
            ), Pairs).

item_depends(item(_, _, any, _), _) :-
    !.
item_depends(item(_, _, Deps, _), P) :-
    ord_memberchk(P, Deps).

%   A true conjunction stays true when triples are only added; a false
%   one becomes true only through a seeded solution.

truth_outcome(truth(true), _, _, _, RemovePairs, truth(true)) :-
    RemovePairs == [].
truth_outcome(truth(false), Ctx, Query, AddPairs, _, truth(Truth)) :-
    (   AddPairs == []
    ->  Truth = false
    ;   seeds(AddPairs, Ctx, Query, Seeds),
        (   seeded_solution(Seeds, Ctx, Query)
        ->  Truth = true
        ;   Truth = false
        )
    ).

%   lost_values(+RemovePairs, +Id, +Ctx, +Query, -Lost): the values no
%   longer holding.  A lost value is the subject or object (or one of
%   their sameAs individuals) of a removed triple when the template is
%   the subject or object of every pattern concerned; otherwise any
%   value may be lost, and the watcher is evaluated in full.

lost_values([], _, _, _, []) :-
    !.
lost_values(RemovePairs, Id, Model-Same, Query, Lost) :-
    \+ memberchk(item(_, _, _, false)-_, RemovePairs),
    findall(V, ( member(_-t(S, _, O), RemovePairs),
                 (   X = S
                 ;   X = O
                 ),
                 same_individual(Same, X, V),
                 watcher_value(V, Id)
               ), Candidates0),
    sort(Candidates0, Candidates),
    exclude(value_holds(Model, Query), Candidates, Lost).

%   value_holds(+Model, +Query, +Value): Value is still a value of the
%   template, as a full evaluation finds them.  A literal in a pattern
%   matches the literals of equal value (3 matches 3.0), while the
%   values found are the literals themselves: a literal that holds so
%   is checked again among the values the patterns give.

value_holds(Model, Query, Value) :-
    copy_term(Query, query(Value, Triples)),
    \+ \+ oro_solve(Model, Triples),
    (   Value = literal(_)
    ->  copy_term(Query, query(Template, AnyTriples)),
        \+ \+ ( oro_solve(Model, AnyTriples),
                Template == Value
              )
    ;   true
    ).

new_values([], _, _, _, []) :-
    !.
new_values(AddPairs, Id, Ctx, Query, New) :-
    seeds(AddPairs, Ctx, Query, Seeds),
    Ctx = Model-_,
    findall(V, ( member(Seed, Seeds),
                 seeded_query(Seed, Query, Template, Triples),
                 oro_find_values(Model, Template, Triples, Vs),
                 member(V, Vs),
                 \+ watcher_value(V, Id)
               ), New0),
    sort(New0, New).

seeded_solution(Seeds, Model-_, Query) :-
    member(Seed, Seeds),
    seeded_query(Seed, Query, _, Triples),
    oro_solve(Model, Triples),
    !.

%   seeded_query(+Seed, +Query, -Template, -Triples): a copy of Query
%   with the subject and object of pattern I bound as Seed says.

seeded_query(seed(I, S1, O1), Query, Template, Triples) :-
    copy_term(Query, query(Template, Triples)),
    nth1(I, Triples, rdf(S, _, O)),
    bind(S, S1),
    bind(O, O1).

bind(Term, Value) :-
    (   var(Value)
    ->  true
    ;   var(Term)
    ->  Term = Value
    ;   true                                % checked by seed_fits/2
    ).

%   seeds(+AddPairs, +Ctx, +Query, -Seeds): seed(I, S, O) terms, the
%   subject and object pattern I may take in an instance the added
%   triples made true (O unbound for a type).  Throws oro_events_full
%   past max_seeds/1.

seeds(AddPairs, Ctx, query(_, Triples), Seeds) :-
    findall(seed(I, S1, O1),
            ( member(item(I, Kind, _, _)-t(S, P, O), AddPairs),
              nth1(I, Triples, rdf(PS, _, PO)),
              seed(Kind, Ctx, S, P, O, PS, PO, S1, O1)
            ), Seeds0),
    sort(Seeds0, Seeds),
    length(Seeds, N),
    max_seeds(Max),
    (   N =< Max
    ->  true
    ;   throw(oro_events_full)
    ).

seed(step, _-Same, S, _, O, PS, PO, S1, O1) :-
    step_seed(Same, S, O, PS, PO, S1, O1).
seed(type, _-Same, S, _, O, PS, _, S1, _) :-
    (   X = S
    ;   X = O
    ),
    atom(X),
    same_individual(Same, X, S1),
    seed_fits(PS, S1).
seed(trans(_), _-Same, S, _, O, PS, PO, S1, O1) :-
    step_seed(Same, S, O, PS, PO, S1, O1).
seed(trans(Transitives), Ctx, S, P, O, PS, PO, S1, O1) :-
    member(T-TDeps, Transitives),
    ord_memberchk(P, TDeps),
    (   X = S, Y = O
    ;   X = O, Y = S
    ),
    atom(X),
    atom(Y),
    chain_ends(Ctx, T, X, Y, PS, PO, S1, O1).

%   An instance made by a triple `s q o` without transitivity: its
%   subject and object are s and o, either way round, or their sameAs
%   individuals.

step_seed(Same, S, O, PS, PO, S1, O1) :-
    (   X = S, Y = O
    ;   X = O, Y = S
    ),
    atom(X),
    same_individual(Same, X, S1),
    seed_fits(PS, S1),
    same_individual(Same, Y, O1),
    seed_fits(PO, O1).

%   Through a transitive T, an edge X→Y makes A T B true for A reaching
%   X and B reached from Y (themselves included); the pattern's
%   instance is A-B or B-A.  Both sets are computed once, filtered by
%   the constants of the pattern, and must stay small.

chain_ends(Model-Same, T, X, Y, PS, PO, S1, O1) :-
    findall(A, ( same_individual(Same, X, A)
               ; oro_holds(Model, A, T, X)
               ), As0),
    sort(As0, As),
    findall(B, ( same_individual(Same, Y, B)
               ; oro_holds(Model, Y, T, B)
               ), Bs0),
    sort(Bs0, Bs),
    include(seed_fits(PS), As, SAs),
    include(seed_fits(PO), Bs, OBs),
    include(seed_fits(PS), Bs, SBs),
    include(seed_fits(PO), As, OAs),
    length(SAs, NSA),
    length(OBs, NOB),
    length(SBs, NSB),
    length(OAs, NOA),
    max_seeds(Max),
    (   NSA * NOB + NSB * NOA =< Max
    ->  true
    ;   throw(oro_events_full)
    ),
    (   member(S1, SAs),
        member(O1, OBs)
    ;   member(S1, SBs),
        member(O1, OAs)
    ).

%   seed_fits(+PatternTerm, +Value): Value may stand at a position of
%   the pattern holding PatternTerm: a variable, the same resource, or
%   a literal (compared by value when the pattern is solved).

seed_fits(Term, Value) :-
    (   var(Term)
    ->  true
    ;   Term == Value
    ->  true
    ;   Term = literal(_)
    ->  Value = literal(_)
    ).

%   same_individual(+Same, +X, -Y): Y is X or one of its sameAs
%   individuals (a literal is only itself).

same_individual(Same, X, Y) :-
    (   atom(X),
        get_assoc(X, Same, Ys)
    ->  member(Y, Ys)
    ;   Y = X
    ).
